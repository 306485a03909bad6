// The calibrated stiffness model on the GPU solver, on the real GL driver (llvmpipe where there
// is no GPU): the scenes and criteria of tests/cpu/stiffness_test.cpp (tests/stiffness_cases.h),
// in float.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/gpu/gpu_solver.h"
#include "tests/gpu/gl_fixture.h"
#include "tests/gpu/gpu_solver_fixture.h"
#include "tests/stiffness_cases.h"

using namespace csm;

TEST_CASE("GPU stiffness: the default scene at 5e-6, 1e-4 and 1e-2 kg/m agrees after 1 s",
          "[gpu][stiffness][long_run]") {
  test::checkDensityCancels(test::gpuSolver);
}

TEST_CASE("GPU stiffness: a clamped strand sags the same at 8 to 64 substeps", "[gpu][stiffness]") {
  test::checkSagAcrossSubsteps(test::gpuSolver);
}

TEST_CASE("GPU stiffness: the nodding default scene converges as the step shrinks",
          "[gpu][stiffness][long_run]") {
  test::checkSceneConverges(test::gpuSolver);
}

TEST_CASE("GPU stiffness: 30, 60 and 120 frames a second with automatic substeps agree",
          "[gpu][stiffness][long_run]") {
  test::checkFrameRates(test::gpuSolver);
}

TEST_CASE("GPU stiffness: 16, 24 and 32 particles on the same strand sag and swing alike",
          "[gpu][stiffness]") {
  test::checkResolution(test::gpuSolver);
}

TEST_CASE("GPU stiffness: the clamped strand sags as the beam at every window, no hinge",
          "[gpu][stiffness]") {
  test::checkWindowIsNotStiffness(test::gpuSolver);
}

TEST_CASE("GPU stiffness: a clamped strand bent hard by gravity settles as the elastica",
          "[gpu][stiffness][quick]") {
  test::checkLargeDeflection(test::gpuSolver);
}

TEST_CASE("GPU stiffness: at 256 steps a frame the float positions follow the CPU's double",
          "[gpu][stiffness][long_run]") {
  // A step at 256 a frame moves a particle ~10 um while its float position rounds by ~0.02 um:
  // velocities taken as (x - x_old) / h would carry that rounding from step to step; the GPU
  // solver forms them from the step's own displacement instead (shaders/sim/strand_step.comp).
  Scene s = test::defaultScene(50);  // 100 until the suite's time was cut
  s.config.sim.substeps = 256;
  s.config.sim.maxSubsteps = 256;
  const auto cpu = test::runFor([] { return std::make_unique<CpuSolver>(); }, s, 0.5);
  const auto gpu = test::runFor(test::gpuSolver, s, 0.5);
  const double rms = test::rmsDistance(gpu, cpu), tips = test::tipRms(s.groom, gpu, cpu);
  INFO("GPU against CPU after 0.5 s at 256 steps a frame: RMS " << rms * 1000 << " mm, tips "
                                                                << tips * 1000 << " mm");
  CHECK(tips <= 0.002);
  CHECK(rms <= 0.002);
}

TEST_CASE("GPU stiffness: the goals of a free strand keep sum m v", "[gpu][stiffness][quick]") {
  // In float: positions of ~0.3 m round by ~2e-8 m, so a velocity (x - x_old) / h at h = 1/240 s
  // carries ~5e-6 m/s of rounding against the strand's ~0.4 m/s: ~1e-5 per particle, less in
  // the sum of 24. The per-particle weighting the per-region masses replaced moved the momentum
  // by ~2e-2 a step (the CPU reference, in double, keeps it to 1e-13).
  test::checkMomentum(test::gpuSolver, 1e-4);
}
