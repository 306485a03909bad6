#include "sim/gpu/split_view.h"

#include <algorithm>

#include <glm/vec2.hpp>

#include "sim/gpu/buffer_fill.h"

namespace csm::gpu {

void SplitView::attach(const gl::Buffer& buffer, uint64_t texels, uint32_t split) {
  const uint64_t lowTexels = std::min<uint64_t>(texels, split);
  const uint64_t highFirst = texels > split ? split : 0;
  const uint64_t highTexels = texels > split ? texels - split : lowTexels;
  constexpr uint64_t bytes = sizeof(glm::uvec2);
  viewRange(low, buffer, gl::TextureFormat::Rg32ui, 0, GLsizeiptr(lowTexels * bytes));
  viewRange(high, buffer, gl::TextureFormat::Rg32ui, GLintptr(highFirst * bytes),
            GLsizeiptr(highTexels * bytes));
}

void SplitView::bindImages(GLuint lowUnit, GLuint highUnit, gl::ImageAccess access) const {
  low.bindImage(lowUnit, access, gl::TextureFormat::Rg32ui);
  high.bindImage(highUnit, access, gl::TextureFormat::Rg32ui);
}

}  // namespace csm::gpu
