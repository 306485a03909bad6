// The baselines (sim/baselines) and the stability claims of docs/BENCHMARKS.md: CSM stays
// bounded at a time step and stiffness where explicit mass-springs diverge.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "sim/solver/baselines/make_baseline.h"
#include "sim/solver/cpu_solver.h"
#include "sim/core/pose.h"
#include "sim/verify/measure.h"
#include "sim/solver/accuracy.h"
#include "sim/verify/solver_head.h"

using namespace csm;

namespace {

// Four straight 25 cm strands of 16 particles held out horizontally from their roots and
// released: no head, no wind, nothing driving. CSM with the paper's stiffness model (w = 2
// particles, alpha = 1), whose stability these claims are about.
Scene cantilevers(int substeps) {
  Scene s;
  for (int k = 0; k < 4; ++k) {
    const double a = 0.5 * M_PI * k;
    const glm::dvec3 dir(std::cos(a), 0.0, std::sin(a));
    std::vector<glm::vec3> pts;
    for (int i = 0; i < 16; ++i) pts.emplace_back(glm::vec3(dir * (0.25 * i / 15)));
    s.groom.addStrand(pts);
  }
  s.config.sim.substeps = substeps;
  s.config.sim.stiffnessModel = StiffnessModel::Paper;
  s.config.collision.mode = CollisionMode::Off;
  s.config.wind.strength = 0.0f;
  s.config.head.motion = HeadMotion::None;
  s.config.head.spheres = {{{0.0f, 10.0f, 0.0f}, 0.01f}};
  return s;
}

// Stretch stiffness that holds the hanging strand's own-weight stretch near 0.01%: as stiff as
// the strain-limited CSM strand.
BaselineParams stiffSprings() {
  BaselineParams p;
  p.stretchStiffness = 1.0;
  p.bendStiffness = 0.2;
  return p;
}

}  // namespace

TEST_CASE(
    "CSM stays bounded at h = 1/240 s where explicit mass-springs of like stiffness "
    "diverge",
    "[quick]") {
  const Scene scene = cantilevers(4);  // h = 1/240 s, the default preset's step

  auto springs = makeBaseline("ms-explicit", stiffSprings());
  const StabilityResult ms = checkStability(*springs, scene, 1.0);
  INFO("mass-spring: " << blowupName(ms.blowup) << " at t = " << ms.time << " s, stretch "
                       << ms.maxStrain);
  CHECK(ms.blowup != Blowup::None);
  CHECK(ms.time < 0.5);

  CpuSolver csm;
  const StabilityResult r = checkStability(csm, scene, 1.0);
  INFO("CSM: " << blowupName(r.blowup) << ", stretch " << r.maxStrain << ", energy x"
               << r.energyRatio);
  CHECK(r.blowup == Blowup::None);
  CHECK(r.maxStrain <= scene.config.sim.strainLimit + 1e-6);

  // The springs themselves are sound: the same scene at h = 1/15360 s stays bounded.
  auto small = makeBaseline("ms-explicit", stiffSprings());
  const StabilityResult fine = checkStability(*small, cantilevers(256), 0.25);
  CHECK(fine.blowup == Blowup::None);
  CHECK(fine.maxStrain < 0.05);
}

TEST_CASE("implicit mass-springs stay bounded at h = 1/60 s with the same springs", "[quick]") {
  auto springs = makeBaseline("ms-implicit", stiffSprings());
  const StabilityResult r = checkStability(*springs, cantilevers(1), 1.0);
  CHECK(r.blowup == Blowup::None);
  CHECK(r.maxStrain < 0.2);
}

TEST_CASE("CSM's strain-limiting sweep gains energy at large steps and DFTL removes it",
          "[quick]") {
  // w = 1, h = 1/120 s: the sweep, which never moves a parent for its child, whips the tips.
  Scene scene = cantilevers(2);
  scene.config.sim.stiffnessWindow = 1;
  CpuSolver plain;
  const StabilityResult gain = checkStability(plain, scene, 2.0, 1.0, 1e9);
  CHECK(gain.energyRatio > 1.5);
  scene.config.sim.dftl = 0.9f;
  CpuSolver corrected;
  const StabilityResult fixed = checkStability(corrected, scene, 2.0, 1.0, 1e9);
  CHECK(fixed.energyRatio < 1.1);
  CHECK(fixed.maxStrain <= scene.config.sim.strainLimit + 1e-6);
}

TEST_CASE("every baseline keeps a strand at rest without forces and its roots on the head",
          "[quick]") {
  // 32 substeps: within the explicit springs' stability limit.
  Scene scene = cantilevers(32);
  scene.config.sim.gravity = glm::vec3(0.0f);
  for (const std::string& name : baselineNames()) {
    auto solver = makeBaseline(name, BaselineParams{});
    // The head turns 30 degrees about y over the run: roots follow it, the rest goes along.
    resetWithHead(*solver, scene.groom, scene.config, Pose{});
    std::vector<glm::vec4> before;
    solver->readPositions(before);
    Pose last;
    for (int f = 0; f < 30; ++f) {
      const Pose from = rotationAbout({0, 0, 0}, {0, 1, 0}, f);
      const Pose to = rotationAbout({0, 0, 0}, {0, 1, 0}, f + 1);
      solver->stepFrame(from, to);
      last = to;
    }
    std::vector<glm::vec4> x;
    solver->readPositions(x);
    INFO(name);
    for (size_t s = 0; s < scene.groom.strandCount(); ++s)
      for (uint32_t i = scene.groom.first[s]; i < scene.groom.first[s] + 2; ++i) {
        const glm::dvec3 want = last.apply(glm::dvec3(scene.groom.points[i]));
        CHECK(glm::length(glm::dvec3(glm::vec3(x[i])) - want) < 1e-6);
      }
    const Accuracy a = measureAccuracy(x, std::vector<glm::vec4>(x.size()), scene.groom,
                                       restLengths(scene.groom), {}, 2);
    CHECK(a.nanCount == 0);
    CHECK(std::abs(a.maxStrain) < 0.02);
  }
}

TEST_CASE("every baseline keeps hair out of the head spheres", "[quick]") {
  // Strands fall from above onto a sphere.
  Scene s;
  for (int k = 0; k < 5; ++k) {
    std::vector<glm::vec3> pts;
    for (int i = 0; i < 10; ++i) pts.emplace_back(-0.05f + 0.025f * k, 0.15f, -0.1f + 0.02f * i);
    s.groom.addStrand(pts);
  }
  s.config.head.spheres = {{{0.0f, 0.0f, 0.0f}, 0.1f}};
  s.config.collision.mode = CollisionMode::Head;
  s.config.sim.substeps = 32;  // within the explicit springs' stability limit
  s.config.wind.strength = 0.0f;
  for (const std::string& name : baselineNames()) {
    auto solver = makeBaseline(name, BaselineParams{});
    SceneRunner run(*solver, s);
    run.runTo(1.0);
    std::vector<glm::vec4> x, v;
    solver->readPositions(x);
    solver->readVelocities(v);
    const Accuracy a = measureAccuracy(x, v, s.groom, restLengths(s.groom), s.config.head.spheres,
                                       s.config.sim.pinned);
    INFO(name);
    CHECK(a.nanCount == 0);
    CHECK(a.headPenetrations == 0);
  }
}
