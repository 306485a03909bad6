// The accuracy measures on cases with a known answer (sim/solver/accuracy.h, sim/verify/measure.h).
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "sim/solver/baselines/make_baseline.h"
#include "sim/solver/cpu_solver.h"
#include "sim/verify/measure.h"
#include "sim/solver/accuracy.h"
#include "sim/groom/resample.h"

using namespace csm;

namespace {

// Straight strands of n particles and length L along `dir` from the origin.
Groom straightGroom(int strands, int n, double length, glm::dvec3 dir = {1, 0, 0}) {
  Groom g;
  for (int s = 0; s < strands; ++s) {
    std::vector<glm::vec3> pts;
    const glm::dvec3 root(0.0, 0.0, 0.01 * s);
    for (int i = 0; i < n; ++i) pts.emplace_back(glm::vec3(root + dir * (length * i / (n - 1))));
    g.addStrand(pts);
  }
  return g;
}

std::vector<glm::vec4> asState(const Groom& g, double scale = 1.0) {
  std::vector<glm::vec4> x;
  for (size_t s = 0; s < g.strandCount(); ++s) {
    const glm::vec3 root = g.points[g.first[s]];
    for (uint32_t i = g.first[s]; i < g.first[s + 1]; ++i)
      x.emplace_back(root + float(scale) * (g.points[i] - root), 1.0f);
  }
  return x;
}

Scene restScene() {
  Scene s;
  s.groom = straightGroom(3, 12, 0.2, glm::normalize(glm::dvec3(1, -1, 0.3)));
  s.config.sim.gravity = glm::vec3(0.0f);
  s.config.collision.mode = CollisionMode::Off;
  s.config.wind.strength = 0.0f;
  s.config.head.motion = HeadMotion::None;
  return s;
}

}  // namespace

TEST_CASE("a strand at rest has zero stretch", "[quick]") {
  const Groom g = straightGroom(2, 10, 0.2);
  const std::vector<glm::vec4> x = asState(g), v(x.size(), glm::vec4(0.0f));
  const Accuracy a = measureAccuracy(x, v, g, restLengths(g), {}, 2);
  CHECK(std::abs(a.maxStrain) < 1e-6);
  CHECK(a.meanStrain < 1e-6);
  CHECK(a.nanCount == 0);
}

TEST_CASE("a strand stretched by 10% reports 0.1", "[quick]") {
  const Groom g = straightGroom(2, 10, 0.2);
  const std::vector<glm::vec4> x = asState(g, 1.1), v(x.size(), glm::vec4(0.0f));
  const Accuracy a = measureAccuracy(x, v, g, restLengths(g), {}, 2);
  CHECK(a.maxStrain == Approx(0.1).margin(1e-5));
  CHECK(a.meanStrain == Approx(0.1).margin(1e-5));
}

TEST_CASE("position error of a state against itself and against a 1 mm shift", "[quick]") {
  const Groom g = straightGroom(2, 8, 0.2);
  const std::vector<glm::vec4> x = asState(g);
  std::vector<glm::vec4> y = x;
  for (glm::vec4& p : y) p.y += 0.001f;
  ErrorAccumulator same(g, 2), shifted(g, 2);
  same.add(x, x);
  shifted.add(x, y);
  CHECK(same.result().rmsMm == 0.0);
  CHECK(same.result().maxMm == 0.0);
  CHECK(shifted.result().rmsMm == Approx(1.0).epsilon(1e-4));
  CHECK(shifted.result().maxMm == Approx(1.0).epsilon(1e-4));
}

TEST_CASE("a strand at rest has zero time-step error, for every solver", "[quick]") {
  const Scene scene = restScene();
  const double times[] = {0.25, 0.5};
  std::vector<SolverMaker> makers = {[] { return std::make_unique<CpuSolver>(); }};
  for (const std::string& name : baselineNames())
    makers.push_back([name] { return makeBaseline(name, BaselineParams{}); });
  for (const SolverMaker& make : makers) {
    const PositionError e = timeStepError(make, scene, times, 16);
    INFO(make()->name());
    CHECK(e.rmsMm < 1e-6);
    CHECK(e.maxMm < 1e-6);
  }
}

TEST_CASE("time-step error is positive for a swinging strand and shrinks with the step",
          "[quick]") {
  Scene scene = restScene();
  scene.config.sim.gravity = glm::vec3(0.0f, -9.81f, 0.0f);
  const double times[] = {0.25, 0.5};
  auto make = [] { return makeBaseline("ms-implicit", BaselineParams{}); };
  scene.config.sim.substeps = 1;
  const PositionError coarse = timeStepError(make, scene, times, 16);
  scene.config.sim.substeps = 4;
  const PositionError fine = timeStepError(make, scene, times, 16);
  CHECK(coarse.rmsMm > 0.1);
  CHECK(fine.rmsMm < coarse.rmsMm);
  CHECK(coarse.maxMm >= coarse.rmsMm);
}

TEST_CASE("window and pinned counts from lengths", "[quick]") {
  CHECK(windowForLength(0.04, 0.02) == 2);
  CHECK(windowForLength(0.04, 0.01) == 4);
  CHECK(windowForLength(0.001, 0.02) == 1);  // never below 1
  // The same window length keeps the region's span when the particle count doubles.
  const double length = 0.25;
  const double l16 = length / 15, l31 = length / 30;
  CHECK(windowForLength(2 * l16, l31) == 4);
  CHECK(pinnedForLength(length / 7, length / 7) == 2);
  CHECK(pinnedForLength(length / 7, length / 14) == 3);
  CHECK(pinnedForLength(0.0, 0.01) == 2);
}

TEST_CASE("uniform rod pendulum period", "[quick]") {
  // T = 2 pi sqrt(2L / 3g): L = 0.25 m, g = 9.81.
  CHECK(rodPendulumPeriod(0.25, 9.81) == Approx(2.0 * M_PI * std::sqrt(0.5 / 29.43)));
  CHECK(rodPendulumPeriod(1.5, 9.81) == Approx(2.0 * M_PI * std::sqrt(1.0 / 9.81)));
  // Finite amplitude lengthens the period: 30 degrees, K(sin 15 deg) gives 1.0174.
  CHECK(rodPendulumPeriod(0.25, 9.81, M_PI / 6) / rodPendulumPeriod(0.25, 9.81) ==
        Approx(1.01741).epsilon(1e-4));
}

TEST_CASE("energy: zero hanging at rest, rho g L^2 / 2 held out horizontally", "[quick]") {
  SimConfig sim;
  const double length = 0.2;
  const Groom down = straightGroom(1, 11, length, {0, -1, 0});
  const Groom out = straightGroom(1, 11, length, {1, 0, 0});
  const EnergyMeter meterDown(down, sim), meterOut(out, sim);
  std::vector<glm::vec4> v(11, glm::vec4(0.0f));
  CHECK(std::abs(meterDown(asState(down), v)) < 1e-12);
  const double rhoGL2 = double(sim.density) * 9.81 * length * length / 2.0;
  CHECK(meterOut(asState(out), v) == Approx(rhoGL2).epsilon(1e-5));
  // Moving as a whole at 1 m/s adds half the strand's mass.
  for (glm::vec4& u : v) u.x = 1.0f;
  CHECK(meterDown(asState(down), v) == Approx(0.5 * sim.density * length).epsilon(1e-5));
}

TEST_CASE("hair-hair penetrations: segment pairs closer than the hair radius", "[quick]") {
  const double r = 0.001;
  Groom g;
  // Two parallel strands 0.5 r apart (crossing into each other) and one 5 r away.
  for (double z : {0.0, 0.5 * r, 5.5 * r}) {
    std::vector<glm::vec3> pts;
    for (int i = 0; i < 5; ++i) pts.emplace_back(0.01f * i, 0.0f, float(z));
    g.addStrand(pts);
  }
  const std::vector<glm::vec4> x = asState(g);
  const uint64_t pairs = closeSegmentPairs(x, g, r);
  CHECK(pairs > 0);
  // Only pairs between the first two strands.
  Groom two;
  two.addStrand({g.points.begin(), g.points.begin() + 5});
  two.addStrand({g.points.begin() + 5, g.points.begin() + 10});
  CHECK(closeSegmentPairs(asState(two), two, r) == pairs);
  CHECK(closeSegmentPairs(x, g, 0.1 * r) == 0);
}

TEST_CASE("resampling and sampling a strand", "[quick]") {
  const std::vector<glm::dvec3> line = {{0, 0, 0}, {0.1, 0, 0}, {0.3, 0, 0}};
  const std::vector<glm::dvec3> r = io::resamplePolyline(line, 4);
  REQUIRE(r.size() == 4);
  CHECK(r[1].x == Approx(0.1));
  CHECK(r[3].x == Approx(0.3));
  std::vector<glm::vec4> x;
  for (const glm::dvec3& p : r) x.emplace_back(glm::vec3(p), 1.0f);
  const std::vector<glm::dvec3> s = sampleStrand(x, 0, 4, 7);
  CHECK(s[3].x == Approx(0.15));
  CHECK(centrelineRmsMm(s, s) == 0.0);
}
