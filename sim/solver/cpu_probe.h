// What tests and tools read of the CPU solver at once and the single steps they take: its state in
// double, the rest lengths, the volume's grid, the contacts of the last frame. The frame loop never
// calls these (it reads the state through SolverState and samples through SolverDiagnostics), so
// they stay off the solver's interfaces; the probe is its friend.
//   CpuProbe(cpu).positions()
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/core/pose.h"
#include "sim/core/results.h"
#include "sim/solver/cpu_solver.h"

namespace csm {

class CpuProbe {
 public:
  explicit CpuProbe(CpuSolver& solver) : solver_(solver) {}

  const std::vector<glm::dvec3>& positions() const { return solver_.x_; }
  const std::vector<glm::dvec3>& velocities() const { return solver_.v_; }
  // Positions in double, which SolverState::write would round to float
  // (sim/verify/window_coefficient.h).
  void setPositions(const std::vector<glm::dvec3>& x) { solver_.x_ = x; }
  // Rest length of the segment from particle i to i+1.
  double restLength(size_t i) const { return solver_.restLength_[i]; }
  // One step of length h ending at head pose `head`, outside any frame.
  void step(double h, const Pose& head, const Pose& torso = Pose{}) {
    solver_.step(h, head, torso);
  }
  // Nodes of the volume mode's grid: none unless collision.mode is a volume mode.
  size_t volumeNodes() const { return solver_.volume_.nodes(); }
  // Hair-hair contacts of the last collision pass (zeros when collisions are off).
  const ContactStats& contactStats() const { return solver_.contacts_; }

 private:
  CpuSolver& solver_;
};

}  // namespace csm
