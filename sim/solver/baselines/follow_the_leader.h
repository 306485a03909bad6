// Dynamic follow-the-leader (Mueller, Kim and Chentanez 2012, "Fast Simulation of Inextensible
// Hair and Fur"): after the prediction, one sweep from root to tip puts every particle back at
// its rest distance from its (already final) parent, so strands never stretch; velocities take
// the change in position minus s_damping times the child's correction, which removes the
// "heavy tip" the plain sweep shows. The paper has no bending; BaselineParams::ftlBend adds a
// pass of PBD bending constraints (i - i+2, Mueller et al. 2007) before the sweep. That pass
// and the velocity correction do not combine well: the correction feeds the bending pass's
// work back into the parents, and the stability map shows the energy it gains at small steps.
#pragma once

#include "sim/solver/baselines/baseline_solver.h"

namespace csm {

class FollowTheLeader final : public BaselineSolver {
 public:
  using BaselineSolver::BaselineSolver;
  std::string_view name() const override { return "ftl"; }
  void step(double h, const Pose& head) override;

 private:
  void onReset() override {
    p_ = x_;
    d_.assign(x_.size(), glm::dvec3(0.0));
  }
  std::vector<glm::dvec3> p_, d_;
};

}  // namespace csm
