// A buffer texture: a view of a gl::Buffer's storage that shaders read with texelFetch on a
// samplerBuffer / usamplerBuffer, or load and store as an imageBuffer / uimageBuffer. Move-only
// RAII like gl::Buffer (Magnum's GL/BufferTexture.h).
//
// Why the GPU solver reads through these: on llvmpipe (Mesa 22) every storage-buffer load
// whose address differs per invocation is emitted as a loop over the SIMD lanes with a
// bounds check per component, while a texel fetch is one vector gather: 3x less CPU time per
// vec4 in the contact pass (2.8 vs 0.9 ns, measured). On GPUs both go through the same caches.
// A view also holds more: GL_MAX_TEXTURE_BUFFER_SIZE texels (llvmpipe: 2^27, 2 GiB of RGBA32UI)
// where a storage block holds GL_MAX_SHADER_STORAGE_BLOCK_SIZE bytes (llvmpipe: 128 MiB).
#pragma once

#include "gl/buffer.h"
#include "gl/enums.h"
#include "gl/gl.h"

namespace csm::gl {

class BufferTexture {
 public:
  explicit BufferTexture(NoCreateT) noexcept {}
  // A view of all of `buffer` as texels of `internalFormat` (GL_RGBA32F, GL_R32UI, ...).
  // The buffer must outlive the view, and a reallocated buffer needs attach() again.
  BufferTexture(const Buffer& buffer, GLenum internalFormat);
  // A view of `size` bytes of `buffer` from `offset` (see attachRange).
  BufferTexture(const Buffer& buffer, GLenum internalFormat, GLintptr offset, GLsizeiptr size);
  BufferTexture(const Buffer& buffer, TextureFormat format)
      : BufferTexture(buffer, GLenum(format)) {}
  BufferTexture(const Buffer& buffer, TextureFormat format, GLintptr offset, GLsizeiptr size)
      : BufferTexture(buffer, GLenum(format), offset, size) {}
  ~BufferTexture();
  BufferTexture(const BufferTexture&) = delete;
  BufferTexture& operator=(const BufferTexture&) = delete;
  BufferTexture(BufferTexture&& other) noexcept;
  BufferTexture& operator=(BufferTexture&& other) noexcept;

  // Takes ownership of an existing GL_TEXTURE_BUFFER name (the destructor deletes it).
  static BufferTexture wrap(GLuint id);
  // Gives up ownership: returns the name and leaves this object empty.
  GLuint release() noexcept;

  // Points the view at `buffer` (again, after the buffer was reallocated).
  void attach(const Buffer& buffer, GLenum internalFormat);
  void attach(const Buffer& buffer, TextureFormat format) { attach(buffer, GLenum(format)); }
  // Points the view at `size` bytes of `buffer` from `offset` (a multiple of
  // GL_TEXTURE_BUFFER_OFFSET_ALIGNMENT).
  void attachRange(const Buffer& buffer, GLenum internalFormat, GLintptr offset, GLsizeiptr size);
  void attachRange(const Buffer& buffer, TextureFormat format, GLintptr offset, GLsizeiptr size) {
    attachRange(buffer, GLenum(format), offset, size);
  }
  // Binds for texelFetch on texture unit `unit`.
  void bind(GLuint unit) const;
  // Binds for imageLoad / imageStore on image unit `unit`: `access` GL_READ_ONLY,
  // GL_WRITE_ONLY or GL_READ_WRITE; `format` the view's internal format, which the shader's
  // layout qualifier must name (rgba32ui, rg32ui, ...).
  void bindImage(GLuint unit, GLenum access, GLenum format) const;
  void bindImage(GLuint unit, ImageAccess access, TextureFormat format) const {
    bindImage(unit, GLenum(access), GLenum(format));
  }
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

}  // namespace csm::gl
