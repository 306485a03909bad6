#include "sim/verify/solver_head.h"

#include "sim/head/head_model.h"

namespace csm {

void resetWithHead(Solver& solver, const Groom& groom, const Config& config, const Pose& head) {
  solver.setHead(HeadModel::require(config));
  solver.reset(groom, config, head);
}

}  // namespace csm
