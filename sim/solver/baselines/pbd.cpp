#include "sim/solver/baselines/pbd.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace csm {

void PbdSolver::step(double h, const Pose& head) {
  prepareStep(head);
  const size_t n = x_.size();
  for (uint32_t i = 0; i < n; ++i) {
    if (pinned(i)) {
      p_[i] = rootTarget(i, head);
      continue;
    }
    v_[i] += h * externalAcceleration(i, h);
    p_[i] = x_[i] + h * v_[i];
  }
  const int iterations = std::max(1, params_.iterations);
  // Stiffness per pass so that `iterations` passes give the stiffness asked for (Mueller et
  // al. 2007, section 3.3): k' = 1 - (1 - k)^(1/n).
  auto perPass = [&](double k) {
    return 1.0 - std::pow(1.0 - std::clamp(k, 0.0, 1.0), 1.0 / iterations);
  };
  const double ks = perPass(params_.pbdStretch), kb = perPass(params_.pbdBend);
  auto w = [&](uint32_t i) { return pinned(i) ? 0.0 : invMass_[i]; };
  for (int it = 0; it < iterations; ++it) {
    for (uint32_t i = 0; i < n; ++i) {
      if (restLength_[i] > 0.0)
        projectDistance(p_[i], p_[i + 1], w(i), w(i + 1), restLength_[i], ks);
      // Bending of the pair of segments ending at i + 1, once both of its edges are done.
      if (i >= 1 && bendLength_[i - 1] > 0.0)
        projectDistance(p_[i - 1], p_[i + 1], w(i - 1), w(i + 1), bendLength_[i - 1], kb);
    }
    for (uint32_t i = 0; i < n; ++i)
      if (!pinned(i)) projectOutOfHead(p_[i]);
  }
  for (uint32_t i = 0; i < n; ++i) {
    v_[i] = (p_[i] - x_[i]) / h;
    x_[i] = p_[i];
  }
  damp(h);
}

}  // namespace csm
