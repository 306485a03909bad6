// Position-based dynamics (Mueller, Heidelberger, Hennix and Ratcliff 2007): predict, then
// project distance constraints between neighbours and bending constraints between particles
// two apart, Gauss-Seidel, `iterations` times per step; velocities from the change in position.
#pragma once

#include "sim/solver/baselines/baseline_solver.h"

namespace csm {

class PbdSolver final : public BaselineSolver {
 public:
  using BaselineSolver::BaselineSolver;
  std::string_view name() const override { return "pbd"; }
  void step(double h, const Pose& head) override;

 private:
  void onReset() override { p_ = x_; }
  std::vector<glm::dvec3> p_;
};

}  // namespace csm
