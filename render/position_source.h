// Where the renderer reads this frame's positions when the solver keeps none on the GPU (the
// CPU solvers): the positions read back are uploaded into a buffer here each frame. The GPU
// solver's own SSBO is drawn from directly.
#pragma once

#include <vector>

#include <glm/vec4.hpp>

#include "gl/buffer.h"

namespace csm {

class PositionSource {
 public:
  // The GL name of an SSBO holding `positions` (vec4 per particle).
  unsigned upload(const std::vector<glm::vec4>& positions);
  // Where a reader of positions writes them before upload(scratch()).
  std::vector<glm::vec4>& scratch() { return scratch_; }

 private:
  gl::Buffer buffer_{gl::NoCreate};
  std::vector<glm::vec4> scratch_;
};

}  // namespace csm
