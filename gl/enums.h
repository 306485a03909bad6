#pragma once
// Typed names for the GL constants that the layers above gl/ pass in: formats, attachments,
// pixel layouts, buffer usage and targets, filters, primitives, shader stages. render/ and app/
// say what they mean with them, without GL's own enums, and cannot pass an attachment where a
// format goes (Magnum's GL::TextureFormat and GL::Framebuffer::ColorAttachment do the same).
// The GPU solver (sim/gpu) names them too. gl/'s classes take them beside their GLenum
// overloads, which gl/'s own code and its tests use; a name is added here when a caller needs it.
#include "gl/gl.h"

namespace csm::gl {

// A texture's, renderbuffer's or buffer texture's internal format (the 32-bit ones are the
// GPU solver's texel views of its buffers and its image loads and stores).
enum class TextureFormat : GLenum {
  Rgba8 = GL_RGBA8,
  Rgba16f = GL_RGBA16F,
  Depth24 = GL_DEPTH_COMPONENT24,
  Depth32f = GL_DEPTH_COMPONENT32F,
  R32f = GL_R32F,
  Rg32f = GL_RG32F,
  Rgba32f = GL_RGBA32F,
  Rgba32i = GL_RGBA32I,
  R32ui = GL_R32UI,
  Rg32ui = GL_RG32UI,
  Rgba32ui = GL_RGBA32UI,
};
// What a shader does with an image unit: imageLoad, imageStore or both.
enum class ImageAccess : GLenum {
  ReadOnly = GL_READ_ONLY,
  WriteOnly = GL_WRITE_ONLY,
  ReadWrite = GL_READ_WRITE,
};

// Where a framebuffer's draws go and its reads come from. WindowBack is the default
// framebuffer's back buffer: what a window shows after the next swap. None, in a list of draw
// buffers, writes no colour (a depth-only pass).
enum class Attachment : GLenum {
  Color0 = GL_COLOR_ATTACHMENT0,
  Depth = GL_DEPTH_ATTACHMENT,
  WindowBack = GL_BACK,
  None = GL_NONE,
};
// Which of a framebuffer's bindings: draws, reads, or both.
enum class FramebufferTarget : GLenum {
  Both = GL_FRAMEBUFFER,
  Draw = GL_DRAW_FRAMEBUFFER,
  Read = GL_READ_FRAMEBUFFER,
};

// The layout of pixels read back or uploaded: the components and the type of each.
enum class PixelFormat : GLenum {
  Rgb = GL_RGB,
  Rgba = GL_RGBA,
};
enum class PixelType : GLenum {
  UnsignedByte = GL_UNSIGNED_BYTE,
  Float = GL_FLOAT,
};
// The type of a vertex attribute's components in its buffer.
enum class AttributeType : GLenum {
  Float = GL_FLOAT,
};

// How a texture is sampled between and beyond its texels.
enum class Filter : GLenum {
  Nearest = GL_NEAREST,
  Linear = GL_LINEAR,
};
enum class Wrap : GLenum {
  ClampToEdge = GL_CLAMP_TO_EDGE,
};
// How a depth texture sampled as a shadow map compares the reference with what it holds.
enum class DepthCompare : GLenum {
  LessOrEqual = GL_LEQUAL,
};

// How a buffer's store is written and read (the driver's hint for where to keep it).
enum class BufferUsage : GLenum {
  StaticDraw = GL_STATIC_DRAW,    // written once by the CPU, read by draws and shaders
  DynamicDraw = GL_DYNAMIC_DRAW,  // written often by the CPU (uniforms a frame)
  DynamicCopy = GL_DYNAMIC_COPY,  // written by the GPU (shaders, copies), read by the GPU
  StreamRead = GL_STREAM_READ,    // written by the GPU, read back by the CPU (staging)
};
// An indexed binding point a buffer is bound to for shaders.
enum class BufferTarget : GLenum {
  ShaderStorage = GL_SHADER_STORAGE_BUFFER,
  Uniform = GL_UNIFORM_BUFFER,
};

// What a draw's vertices make.
enum class Primitive : GLenum {
  Triangles = GL_TRIANGLES,
  Lines = GL_LINES,
};

// A program's stage.
enum class ShaderStage : GLenum {
  Vertex = GL_VERTEX_SHADER,
  Fragment = GL_FRAGMENT_SHADER,
  Compute = GL_COMPUTE_SHADER,
};

}  // namespace csm::gl
