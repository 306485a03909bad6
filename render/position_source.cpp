#include "render/position_source.h"

namespace csm {

unsigned PositionSource::update(Solver& solver) {
  if (unsigned gpu = solver.positionBuffer(); gpu != 0) return gpu;
  solver.readPositions(scratch_);
  if (buffer_.id() == 0) buffer_ = gl::Buffer();
  if (scratch_.empty()) return buffer_.id();
  buffer_.upload(scratch_);
  return buffer_.id();
}

FrameView frameViewOf(const Simulation& sim, const ViewConfig& view, unsigned positionBuffer,
                      int width, int height, unsigned framebuffer) {
  FrameView v;
  v.scene = &sim.config();
  v.look = &view;
  v.groom = &sim.groom();
  v.generation = sim.generation();
  v.head = &sim.head();
  v.headPose = sim.headPose();
  v.positionBuffer = positionBuffer;
  v.width = width;
  v.height = height;
  v.targetFramebuffer = framebuffer;
  return v;
}

}  // namespace csm
