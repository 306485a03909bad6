#include "sim/verify/measure.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "sim/verify/points.h"
#include "sim/core/segment_pairs.h"
#include "sim/core/hair_state.h"
#include "sim/core/pose.h"
#include "sim/solver/accuracy.h"
#include "sim/solver/stiffness.h"
#include "sim/verify/solver_head.h"

namespace csm {

SceneRunner::SceneRunner(Solver& solver, const Scene& scene) : solver_(&solver), scene_(scene) {
  resetWithHead(*solver_, scene.groom, scene.config, headPose(scene.config.head, 0.0));
}

SceneRunner::SceneRunner(const SolverMaker& make, const Scene& scene)
    : owned_(make()), solver_(owned_.get()), scene_(scene) {
  if (solver_) resetWithHead(*solver_, scene.groom, scene.config, headPose(scene.config.head, 0.0));
}

void SceneRunner::frame() {
  const double dt = scene_.config.sim.dt;
  const Pose from = headPose(scene_.config.head, frames_ * dt);
  const Pose to = headPose(scene_.config.head, (frames_ + 1) * dt);
  solver_->stepFrame(from, to);
  ++frames_;
}

double SceneRunner::timedFrame() {
  using Clock = std::chrono::steady_clock;
  solver_->diagnostics().finish();
  const auto t0 = Clock::now();
  frame();
  solver_->diagnostics().finish();
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

void SceneRunner::runTo(double t) {
  const double dt = scene_.config.sim.dt;
  while (time() < t - 0.5 * dt) frame();
}

void ErrorAccumulator::add(std::span<const glm::vec4> a, std::span<const glm::vec4> b) {
  for (size_t s = 0; s < groom_->strandCount(); ++s)
    for (uint32_t i = groom_->first[s] + pinned_; i < groom_->first[s + 1]; ++i) {
      const double d = glm::length(d3(a[i]) - d3(b[i]));
      const double dmm = std::isfinite(d) ? d * 1000.0 : INFINITY;
      sum2_ += dmm * dmm;
      max_ = std::max(max_, dmm);
      ++count_;
    }
}

PositionError ErrorAccumulator::result() const {
  if (count_ == 0) return {};
  return {std::sqrt(sum2_ / double(count_)), max_};
}

PositionError timeStepError(const SolverMaker& make, const Scene& scene,
                            std::span<const double> times, int ratio) {
  Scene fine = scene;
  fine.config.sim.substeps = std::max(1, scene.config.sim.substeps) * ratio;
  std::unique_ptr<Solver> coarseSolver = make(), fineSolver = make();
  SceneRunner coarse(*coarseSolver, scene), reference(*fineSolver, fine);
  ErrorAccumulator acc(scene.groom, scene.config.sim.pinned);
  std::vector<glm::vec4> a, b;
  for (double t : times) {
    coarse.runTo(t);
    reference.runTo(t);
    coarse.readPositions(a);
    reference.readPositions(b);
    acc.add(a, b);
  }
  return acc.result();
}

std::vector<glm::dvec3> sampleStrand(std::span<const glm::vec4> x, uint32_t a, uint32_t b,
                                     int samples) {
  std::vector<glm::dvec3> out(samples);
  const int n = int(b - a);
  for (int k = 0; k < samples; ++k) {
    const double u = double(k) / std::max(1, samples - 1) * (n - 1);
    const int i = std::min(n - 2, int(std::floor(u)));
    const double f = u - i;
    out[k] = glm::mix(d3(x[a + i]), d3(x[a + i + 1]), f);
  }
  return out;
}

double centrelineRmsMm(std::span<const glm::dvec3> a, std::span<const glm::dvec3> b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    const glm::dvec3 d = a[i] - b[i];
    sum += glm::dot(d, d);
  }
  return a.empty() ? 0.0 : 1000.0 * std::sqrt(sum / double(a.size()));
}

int windowForLength(double windowLength, double segmentLength) {
  if (segmentLength <= 0.0) return 1;
  return std::max(1, int(std::lround(windowLength / segmentLength)));
}

int pinnedForLength(double clampLength, double segmentLength) {
  if (segmentLength <= 0.0) return 2;
  return std::max(2, 1 + int(std::lround(clampLength / segmentLength)));
}

Scene cantileverScene(int particles, double length, int strands) {
  Scene s;
  for (int k = 0; k < strands; ++k) {
    // Strands fan out around the vertical so that several can share one scene.
    const double a = 2.0 * M_PI * k / std::max(1, strands);
    const glm::dvec3 dir(std::cos(a), 0.0, std::sin(a));
    const glm::dvec3 root = 0.002 * double(k / 64) * glm::dvec3(0, 1, 0);
    std::vector<glm::vec3> pts;
    for (int i = 0; i < particles; ++i)
      pts.emplace_back(glm::vec3(root + dir * (length * i / (particles - 1))));
    s.groom.addStrand(pts);
  }
  Config& c = s.config;
  // The same clamped length in both stiffness models: a count for the paper's, a length for
  // the calibrated one (equal here, as the particles are evenly spaced).
  c.sim.pinned = pinnedForLength(length / 7.0, length / (particles - 1));
  c.sim.rootLength = float(length / 7.0);
  c.collision.mode = CollisionMode::Off;
  c.wind.strength = 0.0f;
  c.head.motion = HeadMotion::None;
  c.head.spheres = {{{0.0f, 10.0f, 0.0f}, 0.01f}};  // out of the way
  c.head.fitSpheres = false;
  return s;
}

double clampTurnDegrees(const Scene& scene, std::span<const glm::vec4> x) {
  const SimConfig& sim = scene.config.sim;
  const int p = buildRegions(makeHairState(scene.groom, sim, Pose{}), sim).pinned[0] - 1;
  const uint32_t end = scene.groom.first[1];
  if (p < 1 || uint32_t(p) + 1 >= end) return 0.0;
  const glm::dvec3 held = glm::normalize(d3(x[p]) - d3(x[p - 1]));
  const glm::dvec3 next = glm::normalize(d3(x[p + 1]) - d3(x[p]));
  return glm::degrees(std::acos(std::clamp(glm::dot(held, next), -1.0, 1.0)));
}

EnergyMeter::EnergyMeter(const Groom& groom, const SimConfig& sim) : first_(groom.first) {
  const HairState st = makeHairState(groom, sim, Pose{});
  mass_.resize(st.particleCount());
  arc_.assign(st.particleCount(), 0.0);
  for (size_t i = 0; i < mass_.size(); ++i) mass_[i] = st.rest[i].w;
  for (size_t s = 0; s < groom.strandCount(); ++s)
    for (uint32_t i = groom.first[s] + 1; i < groom.first[s + 1]; ++i)
      arc_[i] = arc_[i - 1] + glm::length(glm::dvec3(groom.points[i] - groom.points[i - 1]));
  const glm::dvec3 g(sim.gravity);
  g_ = glm::length(g);
  up_ = g_ > 0.0 ? -g / g_ : glm::dvec3(0.0, 1.0, 0.0);
}

double EnergyMeter::operator()(std::span<const glm::vec4> x, std::span<const glm::vec4> v) const {
  double e = 0.0;
  for (size_t s = 0; s + 1 < first_.size(); ++s) {
    const uint32_t a = first_[s], b = first_[s + 1];
    const double rootHeight = glm::dot(d3(x[a]), up_);
    for (uint32_t i = a; i < b; ++i) {
      const double height = glm::dot(d3(x[i]), up_) - (rootHeight - arc_[i]);
      const glm::dvec3 vi = d3(v[i]);
      e += mass_[i] * (0.5 * glm::dot(vi, vi) + g_ * height);
    }
  }
  return e;
}

const char* blowupName(Blowup b) {
  switch (b) {
    case Blowup::None:
      return "stable";
    case Blowup::Nan:
      return "nan";
    case Blowup::Stretch:
      return "stretch";
    case Blowup::Energy:
      return "energy";
  }
  return "?";
}

StabilityResult checkStability(Solver& solver, const Scene& scene, double duration,
                               double maxStretch, double maxEnergyRatio) {
  SceneRunner run(solver, scene);
  const EnergyMeter energy(scene.groom, scene.config.sim);
  const std::vector<double> rest = restLengths(scene.groom);
  std::vector<glm::vec4> x, v;
  run.readPositions(x);
  run.readVelocities(v);
  const double e0 = std::max(energy(x, v), 1e-300);
  StabilityResult r;
  r.stiffness = run.diagnostics().stiffness();
  while (run.time() < duration - 0.5 * scene.config.sim.dt) {
    run.frame();
    run.readPositions(x);
    run.readVelocities(v);
    r.time = run.time();
    const Accuracy acc = measureAccuracy(x, v, scene.groom, rest, {}, scene.config.sim.pinned);
    if (acc.nanCount > 0) {
      r.blowup = Blowup::Nan;
      r.maxStrain = INFINITY;
      return r;
    }
    r.maxStrain = std::max(r.maxStrain, acc.maxStrain);
    r.energyRatio = std::max(r.energyRatio, energy(x, v) / e0);
    if (!std::isfinite(r.energyRatio)) {
      r.blowup = Blowup::Nan;
      return r;
    }
    if (acc.maxStrain > maxStretch) {
      r.blowup = Blowup::Stretch;
      return r;
    }
    if (r.energyRatio > maxEnergyRatio) {
      r.blowup = Blowup::Energy;
      return r;
    }
  }
  return r;
}

StabilityResult checkStability(const SolverMaker& make, const Scene& scene, double duration,
                               double maxStretch, double maxEnergyRatio) {
  std::unique_ptr<Solver> solver = make();
  if (!solver) return {};
  return checkStability(*solver, scene, duration, maxStretch, maxEnergyRatio);
}

double rodPendulumPeriod(double length, double gravity, double amplitude) {
  const double t0 = 2.0 * M_PI * std::sqrt(2.0 * length / (3.0 * gravity));
  // T = T0 (2/pi) K(sin(theta0/2)) = T0 (1 + theta0^2/16 + 11 theta0^4/3072 + ...).
  const double a2 = amplitude * amplitude;
  return t0 * (1.0 + a2 / 16.0 + 11.0 * a2 * a2 / 3072.0);
}

Scene pendulumScene(int particles, double length, double amplitude, double frameDt) {
  Scene s;
  const glm::dvec3 dir(std::sin(amplitude), -std::cos(amplitude), 0.0);
  std::vector<glm::vec3> pts;
  for (int i = 0; i < particles; ++i)
    pts.emplace_back(glm::vec3(dir * (length * i / (particles - 1))));
  s.groom.addStrand(pts);
  Config& c = s.config;
  c.sim.dt = float(frameDt);
  c.sim.pinned = 1;
  c.sim.damping = 0.0f;
  c.sim.stiffnessModel = StiffnessModel::Paper;
  c.sim.stiffnessWindow = particles;
  c.collision.mode = CollisionMode::Off;
  c.wind.strength = 0.0f;
  c.head.motion = HeadMotion::None;
  c.head.spheres = {{{0.0f, 10.0f, 0.0f}, 0.01f}};  // out of the way
  c.head.fitSpheres = false;
  return s;
}

PendulumResult measurePendulum(Solver& solver, const Scene& scene, double periods) {
  PendulumResult r;
  const Groom& g = scene.groom;
  const uint32_t a = g.first[0], b = g.first[1];
  double length = 0.0;
  for (uint32_t i = a + 1; i < b; ++i)
    length += glm::length(glm::dvec3(g.points[i]) - glm::dvec3(g.points[i - 1]));
  const glm::dvec3 tip = glm::dvec3(g.points[b - 1]) - glm::dvec3(g.points[a]);
  const double amplitude = std::atan2(std::abs(tip.x), -tip.y);
  const double gravity = glm::length(glm::dvec3(scene.config.sim.gravity));
  r.expected = rodPendulumPeriod(length, gravity, amplitude);
  const HairState st = makeHairState(g, scene.config.sim, Pose{});

  SceneRunner run(solver, scene);
  std::vector<glm::vec4> x;
  auto angle = [&]() {
    glm::dvec3 com(0.0);
    double m = 0.0;
    for (uint32_t i = a; i < b; ++i) {
      com += double(st.rest[i].w) * d3(x[i]);
      m += st.rest[i].w;
    }
    const glm::dvec3 d = com / m - d3(x[a]);
    return std::atan2(d.x, -d.y);
  };
  run.readPositions(x);
  double prev = angle(), prevT = 0.0;
  std::vector<double> crossings;
  while (run.time() < periods * r.expected) {
    run.frame();
    run.readPositions(x);
    if (!finite(x[b - 1])) {
      r.finite = false;
      return r;
    }
    const double now = angle(), t = run.time();
    if ((prev < 0.0) != (now < 0.0) && now != prev)
      crossings.push_back(prevT + (t - prevT) * prev / (prev - now));
    prev = now;
    prevT = t;
  }
  r.crossings = int(crossings.size());
  if (crossings.size() >= 2) {
    // Successive crossings are half a period apart.
    r.period = 2.0 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
    r.relativeError = (r.period - r.expected) / r.expected;
  }
  return r;
}

PendulumResult measurePendulum(const SolverMaker& make, const Scene& scene, double periods) {
  std::unique_ptr<Solver> solver = make();
  if (!solver) return {};
  return measurePendulum(*solver, scene, periods);
}

uint64_t closeSegmentPairs(std::span<const glm::vec4> x, const Groom& groom, double distance) {
  std::vector<glm::dvec3> p(x.size());
  std::vector<uint32_t> strand(x.size());
  for (size_t i = 0; i < x.size(); ++i) p[i] = d3(x[i]);
  for (size_t s = 0; s < groom.strandCount(); ++s)
    for (uint32_t i = groom.first[s]; i < groom.first[s + 1]; ++i) strand[i] = uint32_t(s);
  uint64_t n = 0;
  for (const SegmentPair& pair : findContactsGrid(p, strand, distance))
    if (pair.distance < distance) ++n;
  return n;
}

}  // namespace csm
