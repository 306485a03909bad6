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

}  // namespace csm
