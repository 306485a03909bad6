#include "sim/verify/torture.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <glm/geometric.hpp>

#include "sim/base/format.h"
#include "sim/verify/points.h"
#include "sim/core/hair_state.h"
#include "sim/head/distance_grid.h"
#include "sim/head/head_model.h"
#include "sim/run/simulation.h"
#include "sim/solver/stiffness.h"
#include "sim/solver/wind.h"
#include "sim/solver/accuracy.h"

namespace csm {
namespace {

// The far ends: the for the step (1/240-1/24 s) and the substeps (1-8), the parameter
// table's (sim/param/sim_params.cpp) for the rest; tests/cpu/torture_test.cpp checks them against
// it.
constexpr float kWindowLengthMin = 0.002f, kWindowLengthMax = 0.1f;
constexpr int kPaperWindowMin = 1, kPaperWindowMax = 32;
constexpr float kWindMax = 50.0f;
constexpr float kAmplitudeMax = 180.0f, kFrequencyMax = 10.0f;

const char* motionName(HeadMotion m) {
  static const char* names[] = {"none", "nod", "shake", "spin", "sway", "bounce"};
  return names[int(m)];
}

// The one-factor cells without the collision mode.
std::vector<TortureCell> axes(const Config& base, TortureScope scope, double duration) {
  const bool full = scope == TortureScope::Full;
  std::vector<TortureCell> out;
  auto add = [&](const char* axis, std::string value, auto change) {
    TortureCell c;
    c.axis = axis;
    c.value = std::move(value);
    c.config = base;
    c.duration = duration;
    change(c);
    out.push_back(std::move(c));
  };
  if (full) add("base", "preset", [](TortureCell&) {});
  for (int hz : full ? std::vector<int>{240, 120, 30, 24} : std::vector<int>{240, 24})
    add("dt", format("1/%d s", hz), [&](TortureCell& c) { c.config.sim.dt = 1.0f / float(hz); });
  // The exact count: the calibrated model takes at least sim.substeps and more when the
  // stiffness asks; capped, each cell takes the steps it names (as the stability map does).
  for (int s : full ? std::vector<int>{1, 2, 4, 8} : std::vector<int>{1, 8})
    add("substeps", format("%d (capped)", s), [&](TortureCell& c) {
      c.config.sim.substeps = s;
      c.config.sim.maxSubsteps = s;
    });
  for (float l : full ? std::vector<float>{kWindowLengthMin, 0.01f, 0.04f, kWindowLengthMax}
                      : std::vector<float>{kWindowLengthMin, kWindowLengthMax})
    add("window", format("calibrated %g cm", 100.0 * l), [&](TortureCell& c) {
      c.config.sim.stiffnessModel = StiffnessModel::Calibrated;
      c.config.sim.windowLength = l;
    });
  for (int w : full ? std::vector<int>{kPaperWindowMin, 2, 8, kPaperWindowMax}
                    : std::vector<int>{kPaperWindowMin, kPaperWindowMax})
    add("window", format("paper w %d", w), [&](TortureCell& c) {
      c.config.sim.stiffnessModel = StiffnessModel::Paper;
      c.config.sim.stiffnessWindow = w;
    });
  for (float v :
       full ? std::vector<float>{0.0f, 10.0f, 25.0f, kWindMax} : std::vector<float>{0.0f, kWindMax})
    add("wind", format("%g m/s", double(v)), [&](TortureCell& c) { c.config.wind.strength = v; });
  for (HeadMotion m : {HeadMotion::Nod, HeadMotion::Shake, HeadMotion::Spin, HeadMotion::Sway,
                       HeadMotion::Bounce}) {
    const std::string value =
        m == HeadMotion::Spin ? format("spin %g Hz", double(kFrequencyMax))
        : m == HeadMotion::Bounce
            ? format("bounce %g cm %g Hz", double(kAmplitudeMax), double(kFrequencyMax))
            : format("%s %g deg %g Hz", motionName(m), double(kAmplitudeMax),
                     double(kFrequencyMax));
    add("motion", value, [&](TortureCell& c) {
      c.config.head.motion = m;
      c.config.head.amplitude = kAmplitudeMax;
      c.config.head.frequency = kFrequencyMax;
    });
  }
  // The viewer's drag can turn the head by any angle between two frames: the head is still
  // (the preset's motion off) so that the jump is the only thing that moves it.
  for (const char* turn : {"yaw", "nod"})
    add("jump", format("%s 90 deg", turn), [&](TortureCell& c) {
      c.config.head.motion = HeadMotion::None;
      c.jumpTime = 0.25 * duration;
      const glm::dvec3 axis = turn[0] == 'y' ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
      c.jump = rotationAbout(glm::dvec3(c.config.head.pivot), axis, 90.0);
    });
  return out;
}

// Where a world point lies inside the body the solver collides with: how deep (m, > 0 inside),
// the head's part at the head's pose and the torso's at the torso's.
struct BodyDepth {
  SceneHead body;
  static double inside(const DistanceGrid* field, const std::vector<Sphere>& spheres,
                       const glm::dvec3& x, const Pose& pose) {
    if (field) {
      const glm::dvec3 local = glm::inverse(pose.rotation) * (x - pose.translation);
      return -field->sample(local);
    }
    double deepest = -INFINITY;
    for (const Sphere& s : spheres) {
      const glm::dvec3 c = pose.apply(glm::dvec3(s.center));
      deepest = std::max(deepest, double(s.radius) - glm::length(x - c));
    }
    return deepest;
  }
  double operator()(const glm::dvec3& x, const BodyPose& pose) const {
    const double head = inside(body.field, body.spheres, x, pose.head);
    if (!body.hasTorso()) return head;
    return std::max(head, inside(body.torsoField, body.torsoSpheres, x, pose.torso));
  }
};

// The arc a point of the head frame travels from pose a to pose b as the solvers interpolate
// them within a frame (sim/core/pose.h, interpolate), by chords over 16 pieces.
double arcLength(const Pose& a, const Pose& b, const glm::dvec3& local) {
  double length = 0.0;
  glm::dvec3 prev = a.apply(local);
  for (int k = 1; k <= 16; ++k) {
    const glm::dvec3 p = interpolate(a, b, k / 16.0).apply(local);
    length += glm::length(p - prev);
    prev = p;
  }
  return length;
}

double longestStrand(const Groom& g) {
  double longest = 0.0;
  for (size_t s = 0; s < g.strandCount(); ++s) {
    double l = 0.0;
    for (uint32_t i = g.first[s]; i + 1 < g.first[s + 1]; ++i)
      l += glm::length(glm::dvec3(g.points[i + 1]) - glm::dvec3(g.points[i]));
    longest = std::max(longest, l);
  }
  return longest;
}

}  // namespace

std::string TortureCell::name() const {
  return axis + "=" + value + ", " + collisionModeName(config.collision.mode);
}

std::vector<TortureCell> tortureCells(const Config& base, TortureScope scope, double duration) {
  std::vector<TortureCell> out;
  for (const TortureCell& c : axes(base, scope, duration))
    for (int m = 0; m < int(std::size(kCollisionModeNames)); ++m) {
      TortureCell cell = c;
      cell.config.collision.mode = CollisionMode(m);
      out.push_back(std::move(cell));
    }
  return out;
}

std::string TortureResult::failures() const {
  std::string out;
  auto add = [&](const std::string& s) { out += (out.empty() ? "" : "; ") + s; };
  if (!finite) add(format("non-finite state at frame %ld", nonFiniteFrame));
  if (!stretchOk) add(format("stretch %.4f > limit %.4f", maxStrain, strainLimit));
  if (!headOk)
    add(format("inside the head %.2f mm deep, %llu particles (in %ld frames)", deepestMm,
               (unsigned long long)maxInside, insideFrames));
  if (!speedOk)
    add(format("peak speed %.2f > bound %.2f m/s (frame %ld)", peakSpeed, speedBound,
               peakSpeedFrame));
  return out;
}

TortureResult runTorture(const SolverMaker& make, const TortureCell& cell,
                         const TortureCriteria& criteria) {
  using Clock = std::chrono::steady_clock;
  TortureResult r;
  const Config& config = cell.config;
  r.strainLimit = config.sim.strainLimit;
  r.headChecked = collidesWithHead(config.collision.mode);
  std::unique_ptr<Solver> solver = make();
  if (!solver) {
    r.finite = false;
    return r;
  }
  Simulation sim(std::move(solver));
  std::string error;
  if (!sim.load(config, "", &error)) {
    std::fprintf(stderr, "torture: %s: %s\n", cell.name().c_str(), error.c_str());
    r.finite = false;
    return r;
  }
  const Groom& groom = sim.groom();
  const std::vector<double> rest = restLengths(groom);
  const HairState state = makeHairState(groom, config.sim, Pose{});
  const std::vector<int> pinned = buildRegions(state, config.sim).pinned;
  const BodyDepth depth{sim.head().collider()};
  const double dt = config.sim.dt;
  const double g = glm::length(glm::dvec3(config.sim.gravity));
  r.fallSpeed = std::sqrt(2.0 * g * longestStrand(groom)) + g * dt;

  const long frames = std::lround(cell.duration / dt);
  const long jumpFrame = cell.jumpTime >= 0.0 ? std::lround(cell.jumpTime / dt) : -1;
  std::vector<glm::vec4> x, v;
  const auto start = Clock::now();
  for (long f = 0; f < frames; ++f) {
    if (f == jumpFrame) sim.setUserPose(cell.jump);
    // The speed the motion alone gives a point glued to the head this frame: the user pose
    // is the same at both ends, as a jump is a teleport that the hair should follow.
    const double t0 = sim.time(), t1 = t0 + dt;
    const Pose from = compose(sim.userPose(), headPose(config.head, t0));
    const Pose to = compose(sim.userPose(), headPose(config.head, t1));
    for (const glm::vec3& p : groom.points)
      r.rigidSpeed = std::max(r.rigidSpeed, arcLength(from, to, glm::dvec3(p)) / dt);
    sim.stepFrame();
    sim.readPositions(x);
    sim.readVelocities(v);
    r.frames = f + 1;
    const BodyPose pose{sim.headPose(), sim.torsoPose()};
    uint64_t inside = 0;
    for (size_t s = 0; s < groom.strandCount(); ++s) {
      const uint32_t a = groom.first[s], b = groom.first[s + 1];
      for (uint32_t i = a; i < b; ++i) {
        if (!finite(x[i]) || !finite(v[i])) {
          r.finite = false;
          r.nonFiniteFrame = r.frames;
          break;
        }
        const glm::dvec3 xi = d3(x[i]);
        const double speed = glm::length(d3(v[i]));
        if (speed > r.peakSpeed) r.peakSpeed = speed, r.peakSpeedFrame = r.frames;
        if (config.wind.strength > 0.0f)
          r.windSpeed = std::max(r.windSpeed, glm::length(windVelocity(config.wind, xi, t1)));
        if (i + 1 < b && rest[i] > 0.0 && finite(x[i + 1]))
          r.maxStrain = std::max(r.maxStrain, glm::length(d3(x[i + 1]) - xi) / rest[i] - 1.0);
        if (int(i - a) >= pinned[s]) {
          const double d = depth(xi, pose);
          if (d > 0.0) {
            ++inside;
            r.deepestMm = std::max(r.deepestMm, 1000.0 * d);
          }
        }
      }
      if (!r.finite) break;
    }
    if (!r.finite) break;
    r.maxInside = std::max(r.maxInside, inside);
    r.insideFrames += inside > 0;
  }
  sim.diagnostics().finish();
  r.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  r.stepsPerFrame = sim.diagnostics().stiffness().plan.substeps;
  r.speedBound = criteria.speedFactor * (r.rigidSpeed + r.windSpeed) + r.fallSpeed;
  r.stretchOk = r.maxStrain <= config.sim.strainLimit + criteria.strainTolerance;
  r.headOk = !r.headChecked || r.deepestMm <= criteria.penetrationMm;
  r.speedOk = r.peakSpeed <= r.speedBound;
  return r;
}

}  // namespace csm
