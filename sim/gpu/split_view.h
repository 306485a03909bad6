// An RG32UI buffer seen as two image views, the second from texel `split` on: more texels than
// one view of a buffer texture holds (CSM_IMAGE_*_HIGH in shaders/sim/bindings.glsl). The
// candidate pairs' sides and each frame's candidate lists are read and written through these.
#pragma once

#include <cstdint>

#include "gl/buffer.h"
#include "gl/buffer_texture.h"
#include "gl/enums.h"

namespace csm::gpu {

struct SplitView {
  gl::BufferTexture low{gl::NoCreate}, high{gl::NoCreate};
  // Views `texels` texels of `buffer`: the first `split` in `low`, the rest in `high` (which,
  // when the buffer needs no second view, views the first's texels, never read).
  void attach(const gl::Buffer& buffer, uint64_t texels, uint32_t split);
  void bindImages(GLuint lowUnit, GLuint highUnit, gl::ImageAccess access) const;
};

}  // namespace csm::gpu
