// The pendulum measure: a rigid CSM strand (one region spanning it) swinging from its root has
// the period of a uniform rod, 2 pi sqrt(2L / 3g).
#include <catch2/catch.hpp>

#include "sim/solver/baselines/make_baseline.h"
#include "sim/solver/cpu_solver.h"
#include "sim/verify/measure.h"

using namespace csm;

TEST_CASE("a rigid CSM strand swings with the period of a uniform rod", "[quick]") {
  Scene scene = pendulumScene(16, 0.25, 0.1);
  scene.config.sim.substeps = 8;  // h = 1/480 s
  CpuSolver solver;
  const PendulumResult r = measurePendulum(solver, scene, 4.0);
  INFO("period " << r.period << " s, expected " << r.expected << " s");
  CHECK(r.finite);
  CHECK(r.crossings >= 6);
  // The discrete strand's moment of inertia is the rod's times 1 + 1/(2 x 15^2): +0.1%.
  CHECK(std::abs(r.relativeError) < 0.01);
}

TEST_CASE("the pendulum measure runs every baseline to a finite period", "[quick]") {
  for (const char* name : {"ms-implicit", "pbd", "ftl"}) {
    Scene scene = pendulumScene(16, 0.25, 0.1);
    scene.config.sim.substeps = 4;
    auto solver = makeBaseline(name, BaselineParams{});
    const PendulumResult r = measurePendulum(*solver, scene, 3.0);
    INFO(name << ": period " << r.period << " s, expected " << r.expected << " s");
    CHECK(r.finite);
    CHECK(r.crossings >= 4);
    // No baseline has a rigid mode (a straight run of distance constraints bends freely), so
    // the strand swings as a chain; a hanging chain's first mode is within a few percent.
    CHECK(std::abs(r.relativeError) < 0.15);
  }
}
