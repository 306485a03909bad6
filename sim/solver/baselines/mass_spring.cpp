#include "sim/solver/baselines/mass_spring.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace csm {
namespace {

struct Spring {
  uint32_t i, j;
  double k;  // N/m: EA / rest length
  double rest;
};

// Every spring of the strands: edges (i, i+1) and bending springs (i, i+2).
template <class F>
void forEachSpring(const std::vector<double>& restLength, const std::vector<double>& bendLength,
                   const BaselineParams& p, F&& f) {
  for (uint32_t i = 0; i < restLength.size(); ++i) {
    if (restLength[i] > 1e-9)
      f(Spring{i, i + 1, p.stretchStiffness / restLength[i], restLength[i]});
    if (bendLength[i] > 1e-9 && p.bendStiffness > 0.0)
      f(Spring{i, i + 2, p.bendStiffness / bendLength[i], bendLength[i]});
  }
}

}  // namespace

void ExplicitMassSpring::step(double h, const Pose& head) {
  prepareStep(head);
  for (uint32_t i = 0; i < x_.size(); ++i) force_[i] = mass_[i] * externalAcceleration(i, h);
  forEachSpring(restLength_, bendLength_, params_, [&](const Spring& s) {
    const glm::dvec3 d = x_[s.j] - x_[s.i];
    const double len = glm::length(d);
    if (len < 1e-15) return;
    const glm::dvec3 f = s.k * (len - s.rest) * (d / len);
    force_[s.i] += f;
    force_[s.j] -= f;
  });
  for (uint32_t i = 0; i < x_.size(); ++i) {
    if (pinned(i)) {
      const glm::dvec3 target = rootTarget(i, head);
      v_[i] = (target - x_[i]) / h;
      x_[i] = target;
      continue;
    }
    v_[i] += h * invMass_[i] * force_[i];
    x_[i] += h * v_[i];
    const glm::dvec3 before = x_[i];
    if (projectOutOfHead(x_[i])) v_[i] += (x_[i] - before) / h;
  }
  damp(h);
}

void ImplicitMassSpring::onReset() {
  const Eigen::Index n = Eigen::Index(3 * x_.size());
  A_.resize(n, n);
  b_.resize(n);
  dv_.resize(n);
  analysed_ = false;
}

void ImplicitMassSpring::step(double h, const Pose& head) {
  prepareStep(head);
  const size_t n = x_.size();
  const double h2 = h * h;
  // Kinematic roots: their velocity change is prescribed, and moves to the right-hand side.
  std::vector<glm::dvec3> dvPinned(n, glm::dvec3(0.0));
  for (uint32_t i = 0; i < n; ++i)
    if (pinned(i)) dvPinned[i] = (rootTarget(i, head) - x_[i]) / h - v_[i];

  triplets_.clear();
  auto addBlock = [&](uint32_t r, uint32_t c, const Eigen::Matrix3d& m) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) triplets_.emplace_back(3 * r + a, 3 * c + b, m(a, b));
  };
  auto bAt = [&](uint32_t i) { return b_.segment<3>(3 * Eigen::Index(i)); };
  for (uint32_t i = 0; i < n; ++i) {
    const bool p = pinned(i);
    addBlock(i, i, (p ? 1.0 : mass_[i]) * Eigen::Matrix3d::Identity());
    const glm::dvec3 f = p ? dvPinned[i] : h * mass_[i] * externalAcceleration(i, h);
    bAt(i) = Eigen::Vector3d(f.x, f.y, f.z);
  }
  forEachSpring(restLength_, bendLength_, params_, [&](const Spring& s) {
    const glm::dvec3 dg = x_[s.j] - x_[s.i];
    const double len = glm::length(dg);
    const Eigen::Vector3d d(dg.x, dg.y, dg.z);
    Eigen::Matrix3d kb = Eigen::Matrix3d::Zero();
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    if (len > 1e-15) {
      const Eigen::Vector3d u = d / len;
      const Eigen::Matrix3d uu = u * u.transpose();
      // df_i/dx_j; the transverse part is dropped under compression (Choi and Ko 2002).
      kb = s.k * (uu + std::max(0.0, 1.0 - s.rest / len) * (Eigen::Matrix3d::Identity() - uu));
      f = s.k * (len - s.rest) * u;
    }
    const Eigen::Matrix3d a = h2 * kb;  // the blocks of -h^2 K
    const bool pi = pinned(s.i), pj = pinned(s.j);
    const Eigen::Vector3d vi(v_[s.i].x, v_[s.i].y, v_[s.i].z);
    const Eigen::Vector3d vj(v_[s.j].x, v_[s.j].y, v_[s.j].z);
    const Eigen::Vector3d kv = kb * (vj - vi);  // (K v)_i; (K v)_j is its negative
    const Eigen::Vector3d dvi(dvPinned[s.i].x, dvPinned[s.i].y, dvPinned[s.i].z);
    const Eigen::Vector3d dvj(dvPinned[s.j].x, dvPinned[s.j].y, dvPinned[s.j].z);
    if (!pi) {
      addBlock(s.i, s.i, a);
      bAt(s.i) += h * f + h2 * kv;
      if (pj) bAt(s.i) += a * dvj;  // -A_ij dv_j with A_ij = -a
    }
    if (!pj) {
      addBlock(s.j, s.j, a);
      bAt(s.j) += -h * f - h2 * kv;
      if (pi) bAt(s.j) += a * dvi;
    }
    // Off-diagonal blocks, zero where a root is involved so the pattern never changes.
    const Eigen::Matrix3d off = (pi || pj) ? Eigen::Matrix3d::Zero() : Eigen::Matrix3d(-a);
    addBlock(s.i, s.j, off);
    addBlock(s.j, s.i, off);
  });
  A_.setFromTriplets(triplets_.begin(), triplets_.end());
  if (!analysed_) {
    solver_.analyzePattern(A_);
    analysed_ = true;
  }
  solver_.factorize(A_);
  dv_ = solver_.solve(b_);
  for (uint32_t i = 0; i < n; ++i) {
    const glm::dvec3 dv(dv_[3 * i], dv_[3 * i + 1], dv_[3 * i + 2]);
    v_[i] += dv;
    x_[i] += h * v_[i];
    if (pinned(i)) continue;
    const glm::dvec3 before = x_[i];
    if (projectOutOfHead(x_[i])) v_[i] += (x_[i] - before) / h;
  }
  damp(h);
}

}  // namespace csm
