// Where the renderer reads this frame's positions. The GPU solver keeps them in an SSBO of
// its own, which is drawn from directly; the CPU solver has none, so its positions are read
// back and uploaded into a buffer here each frame.
#pragma once

#include <vector>

#include <glm/vec4.hpp>

#include "gl/buffer.h"
#include "sim/core/solver.h"

namespace csm {

class PositionSource {
 public:
  // The GL name of an SSBO with `solver`'s current positions (vec4 per particle).
  unsigned update(Solver& solver);

 private:
  gl::Buffer buffer_{gl::NoCreate};
  std::vector<glm::vec4> scratch_;
};

}  // namespace csm
