#include "render/position_source.h"

namespace csm {

unsigned PositionSource::upload(const std::vector<glm::vec4>& positions) {
  if (buffer_.id() == 0) buffer_ = gl::Buffer();
  if (positions.empty()) return buffer_.id();
  buffer_.upload(positions);
  return buffer_.id();
}

}  // namespace csm
