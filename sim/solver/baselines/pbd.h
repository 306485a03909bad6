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

// Projects the distance constraint |p_i - p_j| = rest with stiffness k (0..1) and inverse
// masses wi, wj (0 = kinematic) (Mueller et al. 2007, section 3.3).
void projectDistance(glm::dvec3& pi, glm::dvec3& pj, double wi, double wj, double rest, double k);

}  // namespace csm
