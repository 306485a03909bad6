#include "sim/solver/baselines/baseline_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>

#include "sim/head/head_model.h"
#include "sim/solver/wind.h"
#include "sim/solver/accuracy.h"
#include "sim/solver/state_io.h"
#include "sim/core/hair_state.h"

namespace csm {

void BaselineSolver::reset(const Groom& groom, const Config& config, const Pose& head) {
  config_ = config;
  time_ = 0.0;
  const HairState st = makeHairState(groom, config.sim, head);
  const size_t n = st.particleCount();
  first_ = st.strandFirst;
  strandOf_ = st.particleStrand;
  tipHeld_ = st.tipHeld;
  rest_.resize(n);
  mass_.resize(n);
  invMass_.resize(n);
  x_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    rest_[i] = glm::dvec3(glm::vec3(st.rest[i]));
    mass_[i] = st.rest[i].w;
    invMass_[i] = 1.0 / mass_[i];
    x_[i] = head.apply(rest_[i]);
  }
  v_.assign(n, glm::dvec3(0.0));
  restLength_.assign(n, 0.0);
  bendLength_.assign(n, 0.0);
  for (size_t i = 0; i + 1 < n; ++i) {
    if (strandOf_[i] == strandOf_[i + 1]) restLength_[i] = glm::length(rest_[i + 1] - rest_[i]);
    if (i + 2 < n && strandOf_[i] == strandOf_[i + 2])
      bendLength_[i] = glm::length(rest_[i + 2] - rest_[i]);
  }
  headSpheres_ = headModel_.collider().spheres;
  failure_ = headModel_.handed() ? std::string() : std::string(kNoHeadFailure);
  spheres_ = worldSpheres(headSpheres_, head);
  samples_.clear();
  onReset();
}

void BaselineSolver::stepFrame(const Pose& from, const Pose& to) {
  const auto t0 = std::chrono::steady_clock::now();
  const int substeps = std::max(1, config_.sim.substeps);
  const double h = double(config_.sim.dt) / substeps;
  if (!failure_.empty()) {
    // No head to collide with (failure()): the clock runs, the hair stays.
    time_ += substeps * h;
    return;
  }
  for (int k = 0; k < substeps; ++k) {
    step(h, interpolate(from, to, double(k + 1) / substeps));
    time_ += h;
  }
  lastMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void BaselineSolver::prepareStep(const Pose& head) {
  spheres_ = worldSpheres(headSpheres_, head);
}

glm::dvec3 BaselineSolver::externalAcceleration(uint32_t i, double h) const {
  glm::dvec3 acc(config_.sim.gravity);
  const WindConfig& wind = config_.wind;
  if (wind.strength > 0.0f && wind.drag > 0.0f) {
    const uint32_t a = first_[strandOf_[i]], b = first_[strandOf_[i] + 1];
    const uint32_t lo = i > a ? i - 1 : i, hi = std::min(i + 1, b - 1);
    const glm::dvec3 d = x_[hi] - x_[lo];
    const double len = glm::length(d);
    const glm::dvec3 t = len > 1e-15 ? d / len : glm::dvec3(0.0);
    const glm::dvec3 rel = windVelocity(wind, x_[i], time_) - v_[i];
    const double c = wind.drag;
    acc += c / (1.0 + h * c) * (rel - glm::dot(rel, t) * t);
  }
  return acc;
}

bool BaselineSolver::projectOutOfHead(glm::dvec3& p) const {
  if (config_.collision.mode == CollisionMode::Off) return false;
  const double r = config_.collision.radius;
  bool any = false;
  // Overlapping spheres can push a point into each other: repeat until it is clear.
  for (int pass = 0; pass < 4; ++pass) {
    bool moved = false;
    for (const Sphere& s : spheres_) {
      const glm::dvec3 c(s.center);
      const glm::dvec3 d = p - c;
      const double rad = s.radius + r;
      const double len2 = glm::dot(d, d);
      if (len2 >= rad * rad) continue;
      const double len = std::sqrt(len2);
      p = c + (len > 1e-15 ? d / len : glm::dvec3(0, 1, 0)) * rad;
      moved = true;
    }
    any |= moved;
    if (!moved) break;
  }
  return any;
}

void BaselineSolver::damp(double h) {
  const double keep = std::exp(-double(config_.sim.damping) * h);
  for (uint32_t i = 0; i < x_.size(); ++i)
    if (!pinned(i)) v_[i] *= keep;
}

void BaselineSolver::readPositions(std::vector<glm::vec4>& out) {
  readDoublePositions(x_, out);
}

void BaselineSolver::readVelocities(std::vector<glm::vec4>& out) {
  readDoubleVelocities(v_, out);
}

void BaselineSolver::writeState(const std::vector<glm::vec4>& positions,
                                const std::vector<glm::vec4>& velocities) {
  writeDoubleState(positions, velocities, x_, v_);
}

void BaselineSolver::requestSample(long frame) {
  FrameSample sample;
  sample.frame = frame;
  const std::vector<int> pinned(first_.size() - 1, config_.sim.pinned);
  sample.accuracy = measureAccuracy(x_, v_, first_, restLength_, spheres_, pinned);
  samples_.push_back(sample);
}

std::optional<FrameSample> BaselineSolver::takeSample(bool) {
  if (samples_.empty()) return std::nullopt;
  FrameSample s = samples_.front();
  samples_.pop_front();
  return s;
}

void projectDistance(glm::dvec3& pi, glm::dvec3& pj, double wi, double wj, double rest, double k) {
  const double w = wi + wj;
  if (w <= 0.0) return;
  const glm::dvec3 d = pi - pj;
  const double len = glm::length(d);
  if (len < 1e-15) return;
  const glm::dvec3 corr = (k * (len - rest) / (w * len)) * d;
  pi -= wi * corr;
  pj += wj * corr;
}

}  // namespace csm
