#pragma once
// Typed names for the GL constants that the layers above gl/ pass in: formats, attachments,
// pixel layouts, buffer usage. render/ and app/ say what they mean with them, without GL's own
// enums, and cannot pass an attachment where a format goes (Magnum's GL::TextureFormat and
// GL::Framebuffer::ColorAttachment do the same). gl/'s classes take them beside their GLenum
// overloads; a name is added here when a caller needs it.
#include "gl/gl.h"

namespace csm::gl {

// A texture's or renderbuffer's internal format.
enum class TextureFormat : GLenum {
  Rgba8 = GL_RGBA8,
};

// Where a framebuffer's draws go and its reads come from. WindowBack is the default
// framebuffer's back buffer: what a window shows after the next swap.
enum class Attachment : GLenum {
  Color0 = GL_COLOR_ATTACHMENT0,
  WindowBack = GL_BACK,
};

// The layout of pixels read back: the components and the type of each.
enum class PixelFormat : GLenum {
  Rgb = GL_RGB,
  Rgba = GL_RGBA,
};
enum class PixelType : GLenum {
  UnsignedByte = GL_UNSIGNED_BYTE,
};

// How a buffer's store is written and read (the driver's hint for where to keep it).
enum class BufferUsage : GLenum {
  DynamicCopy = GL_DYNAMIC_COPY,  // written by the GPU (copies), read by the GPU (draws)
};

}  // namespace csm::gl
