#include "sim/solver/baselines/follow_the_leader.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace csm {

void FollowTheLeader::step(double h, const Pose& head) {
  prepareStep(head);
  const size_t n = x_.size();
  for (uint32_t i = 0; i < n; ++i) {
    d_[i] = glm::dvec3(0.0);
    if (pinned(i)) {
      p_[i] = rootTarget(i, head);
      continue;
    }
    v_[i] += h * externalAcceleration(i, h);
    p_[i] = x_[i] + h * v_[i];
  }
  // Optional bending, which the paper leaves out: one pass of PBD bending constraints before
  // the sweep. Its stiffness is given per 1/60 s and compounded over the step so that substeps
  // do not stiffen the strand (the iteration rule of Mueller et al. 2007, section 3.3, applied
  // to steps): k_h = 1 - (1 - k)^(60 h).
  const double kb = 1.0 - std::pow(1.0 - std::clamp(params_.ftlBend, 0.0, 1.0), 60.0 * h);
  if (kb > 0.0) {
    auto w = [&](uint32_t i) { return pinned(i) ? 0.0 : invMass_[i]; };
    for (uint32_t i = 0; i + 2 < n; ++i)
      if (bendLength_[i] > 0.0)
        projectDistance(p_[i], p_[i + 2], w(i), w(i + 2), bendLength_[i], kb);
  }
  // The sweep: each particle is placed against a parent that is already final.
  for (uint32_t i = 1; i < n; ++i) {
    if (pinned(i) || restLength_[i - 1] <= 0.0) continue;
    const glm::dvec3 before = p_[i];
    const glm::dvec3 dir = p_[i] - p_[i - 1];
    const double len = glm::length(dir);
    if (len > 1e-15) p_[i] = p_[i - 1] + dir * (restLength_[i - 1] / len);
    projectOutOfHead(p_[i]);
    d_[i] = p_[i] - before;
  }
  for (uint32_t i = 0; i < n; ++i) {
    glm::dvec3 v = (p_[i] - x_[i]) / h;
    // v_i -= s_damping d_{i+1} / h (Mueller et al. 2012, eq. 9): the parent takes back part of
    // the velocity the sweep gave its child. Without it the sweep, which never moves a parent
    // for its child, yanks children like a whip and adds energy.
    if (!pinned(i) && i + 1 < n && restLength_[i] > 0.0) v -= params_.ftlDamping * d_[i + 1] / h;
    v_[i] = v;
    x_[i] = p_[i];
  }
  damp(h);
}

}  // namespace csm
