#include "sim/solver/baselines/baseline_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>

#include "sim/head/head_model.h"
#include "sim/solver/wind.h"
#include "sim/solver/accuracy.h"

namespace csm {

void BaselineSolver::reset(const Groom& groom, const Config& config, const Pose& head) {
  layOut(groom, config, head);
  const size_t n = x_.size();
  invMass_.resize(n);
  for (size_t i = 0; i < n; ++i) invMass_[i] = 1.0 / mass_[i];
  bendLength_.assign(n, 0.0);
  for (size_t i = 0; i + 2 < n; ++i)
    if (strandOf_[i] == strandOf_[i + 2]) bendLength_[i] = glm::length(rest_[i + 2] - rest_[i]);
  headSpheres_ = headModel_.collider().spheres;
  torsoSpheres_ = headModel_.collider().torsoSpheres;
  torso_ = head;  // the body as one until a path says otherwise
  prepareStep(head);
  onReset();
}

void BaselineSolver::stepFrame(const FramePath& path) {
  const Pose& to = path.to();
  const auto t0 = std::chrono::steady_clock::now();
  const int substeps = std::max(1, config_.sim.substeps);
  const double h = double(config_.sim.dt) / substeps;
  if (!failure_.empty()) {
    // No head to collide with (failure()): the clock runs, the hair stays.
    time_ += substeps * h;
    head_ = to;
    torso_ = path.torsoAt(1.0);
    return;
  }
  for (int k = 0; k < substeps; ++k) {
    const double s = double(k + 1) / substeps;
    torso_ = path.torsoAt(s);
    step(h, path.at(s));
    time_ += h;
  }
  head_ = to;
  lastMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void BaselineSolver::prepareStep(const Pose& head) {
  spheres_ = worldSpheres(headSpheres_, head);
  for (const Sphere& sp : worldSpheres(torsoSpheres_, torso_)) spheres_.push_back(sp);
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

void BaselineSolver::requestSample(long frame) {
  FrameSample sample;
  sample.frame = frame;
  const std::vector<int> pinned(first_.size() - 1, config_.sim.pinned);
  sample.accuracy = measureAccuracy(x_, v_, first_, restLength_, spheres_, pinned, {},
                                    BodyParts{{}, headSpheres_.size()});
  samples_.push_back(sample);
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
