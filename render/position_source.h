// Where the renderer reads this frame's positions. The GPU solver keeps them in an SSBO of
// its own, which is drawn from directly; the CPU solver has none, so its positions are read
// back and uploaded into a buffer here each frame.
#pragma once

#include <vector>

#include <glm/vec4.hpp>

#include "gl/buffer.h"
#include "render/renderer.h"
#include "sim/run/simulation.h"

namespace csm {

class PositionSource {
 public:
  // The GL name of an SSBO with `solver`'s current positions (vec4 per particle).
  unsigned update(Solver& solver);

 private:
  gl::Buffer buffer_{gl::NoCreate};
  std::vector<glm::vec4> scratch_;
};

// The FrameView of a simulation's current frame seen as `view` says, drawn into
// `framebuffer` at width x height.
FrameView frameViewOf(const Simulation& sim, const ViewConfig& view, unsigned positionBuffer,
                      int width, int height, unsigned framebuffer = 0);

}  // namespace csm
