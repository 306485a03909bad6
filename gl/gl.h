#pragma once
// Common include for the raw-GL layer. Everything in gl works with whatever GL
// context is current (EGL headless or a GLFW window): nothing here depends on EGL
// except context.h.
#include <epoxy/gl.h>  // IWYU pragma: export

namespace csm::gl {

// Tag for constructing a wrapper without a GL object, e.g. a member built before a
// context exists (Magnum's NoCreate). Such an object holds id 0; assign a real one later.
struct NoCreateT {
  explicit constexpr NoCreateT() = default;
};
inline constexpr NoCreateT NoCreate{};

// Which writes must be visible to which later reads; a compute pass that writes an SSBO
// must be followed by a barrier naming how the data is read next (GL 4.6 spec §7.13.2).
enum class Barrier : GLbitfield {
  Storage = GL_SHADER_STORAGE_BARRIER_BIT,            // SSBO reads in later shaders
  VertexAttrib = GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT,  // buffer used as vertex attributes
  ElementArray = GL_ELEMENT_ARRAY_BARRIER_BIT,
  Uniform = GL_UNIFORM_BARRIER_BIT,
  Command = GL_COMMAND_BARRIER_BIT,             // indirect draw/dispatch arguments
  BufferUpdate = GL_BUFFER_UPDATE_BARRIER_BIT,  // glGetBufferSubData, glBufferSubData, copies
  TextureFetch = GL_TEXTURE_FETCH_BARRIER_BIT,
  ImageAccess = GL_SHADER_IMAGE_ACCESS_BARRIER_BIT,
  Framebuffer = GL_FRAMEBUFFER_BARRIER_BIT,
  TextureUpdate = GL_TEXTURE_UPDATE_BARRIER_BIT,  // glGetTexImage, glTexSubImage
  All = GL_ALL_BARRIER_BITS,
};

constexpr Barrier operator|(Barrier a, Barrier b) {
  return Barrier(GLbitfield(a) | GLbitfield(b));
}

inline void memoryBarrier(Barrier bits) {
  glMemoryBarrier(GLbitfield(bits));
}

}  // namespace csm::gl
