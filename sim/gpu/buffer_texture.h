// A buffer texture: a view of a gl::Buffer's storage that shaders read with texelFetch on a
// samplerBuffer. Move-only RAII, like the wrappers in render/gl (Magnum's GL/BufferTexture.h).
//
// Why the solver reads through textures: on llvmpipe (Mesa 22) every storage-buffer load
// whose address differs per invocation is emitted as a loop over the SIMD lanes with a
// bounds check per component, while a texel fetch is one vector gather. In the contact
// pass, which reads ~2,500 candidates per segment, that is 3x less CPU time per candidate
// (2.8 vs 0.9 ns for a vec4, measured). On GPUs both paths go through the same caches.
//
// TODO(render/gl): this belongs next to gl::Texture; it lives here until render/gl has one.
#pragma once

#include "render/gl/buffer.h"
#include "render/gl/gl.h"

namespace csm::gpu {

class BufferTexture {
 public:
  explicit BufferTexture(gl::NoCreateT) noexcept {}
  // A view of all of `buffer` as texels of `internalFormat` (GL_RGBA32F, GL_R32UI, ...).
  // The buffer must outlive the view, and a reallocated buffer needs attach() again.
  BufferTexture(const gl::Buffer& buffer, GLenum internalFormat);
  ~BufferTexture();
  BufferTexture(const BufferTexture&) = delete;
  BufferTexture& operator=(const BufferTexture&) = delete;
  BufferTexture(BufferTexture&& other) noexcept;
  BufferTexture& operator=(BufferTexture&& other) noexcept;

  void attach(const gl::Buffer& buffer, GLenum internalFormat);
  // Binds for texelFetch on texture unit `unit`.
  void bind(GLuint unit) const;
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

}  // namespace csm::gpu
