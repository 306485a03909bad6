// The calibrated stiffness model on the GPU solver, on the real GL driver (llvmpipe where there
// is no GPU): the scenes and criteria of tests/cpu/stiffness_test.cpp (tests/stiffness_cases.h),
// in float.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/gpu/gpu_solver.h"
#include "tests/gpu/gl_fixture.h"
#include "tests/stiffness_cases.h"

using namespace csm;

namespace {

std::unique_ptr<Solver> makeGpu() {
  test::glContext();
  std::string error;
  std::unique_ptr<GpuSolver> gpu = GpuSolver::create(&error);
  INFO(error);
  REQUIRE(gpu);
  return gpu;
}

}  // namespace

TEST_CASE("GPU stiffness: the default scene at 5e-6, 1e-4 and 1e-2 kg/m agrees after 1 s",
          "[gpu][stiffness]") {
  Scene s = test::defaultScene();
  const auto reference = test::runFor(makeGpu, s, 1.0);
  for (float density : {5e-6f, 1e-2f}) {
    s.config.sim.density = density;
    const double rms = test::rmsDistance(test::runFor(makeGpu, s, 1.0), reference);
    INFO("density " << density << ": RMS " << rms << " m from 1e-4 kg/m");
    CHECK(rms < 1e-6);
  }
}

TEST_CASE("GPU stiffness: a clamped strand sags the same at 8 to 64 substeps", "[gpu][stiffness]") {
  const double reference = test::clampedSag(makeGpu, 16, 64);
  CHECK(reference > 0.02);
  for (int substeps : {8, 16, 32}) {
    const double sag = test::clampedSag(makeGpu, 16, substeps);
    INFO(substeps << " substeps: sag " << sag << " m, 64 substeps: " << reference << " m");
    CHECK(std::abs(sag / reference - 1.0) < 0.02);
  }
}

TEST_CASE("GPU stiffness: the nodding default scene converges as the step shrinks",
          "[gpu][stiffness]") {
  const Scene s = test::defaultScene();
  std::vector<std::vector<glm::vec4>> runs;
  for (int substeps : {8, 16, 32, 64}) {
    Scene n = s;
    n.config.sim.substeps = substeps;
    runs.push_back(test::runFor(makeGpu, n, 1.0));
  }
  double previous = 1e30;
  for (size_t k = 0; k + 1 < runs.size(); ++k) {
    const double rms = test::tipRms(s.groom, runs[k], runs[k + 1]);
    INFO((8 << k) << " against " << (16 << k) << " substeps: tip RMS " << rms * 1000 << " mm");
    CHECK(rms <= 0.002);
    CHECK(rms < previous);
    previous = rms;
  }
}

TEST_CASE("GPU stiffness: 30, 60 and 120 frames a second with automatic substeps agree",
          "[gpu][stiffness]") {
  const double sag60 = test::clampedSag(makeGpu, 16, 1, 1.0 / 60.0);
  Scene s = test::defaultScene();
  s.config.sim.substeps = 1;
  const auto at60 = test::runFor(makeGpu, s, 1.0);
  for (double dt : {1.0 / 30.0, 1.0 / 120.0}) {
    const double sag = test::clampedSag(makeGpu, 16, 1, dt);
    Scene f = s;
    f.config.sim.dt = float(dt);
    const double rms = test::tipRms(s.groom, test::runFor(makeGpu, f, 1.0), at60);
    INFO("dt " << dt << ": sag " << sag << " m (" << sag60 << " at 1/60 s), tip RMS " << rms * 1000
               << " mm");
    CHECK(std::abs(sag / sag60 - 1.0) < 0.02);
    CHECK(rms <= 0.005);
  }
}

TEST_CASE("GPU stiffness: 16, 24 and 32 particles on the same strand sag and swing alike",
          "[gpu][stiffness]") {
  const double sag32 = test::clampedSag(makeGpu, 32);
  const auto swing32 = test::swingTip(makeGpu, 32);
  for (int particles : {16, 24}) {
    const double sag = test::clampedSag(makeGpu, particles);
    const double rms = test::pathRms(test::swingTip(makeGpu, particles), swing32);
    INFO(particles << " particles: sag " << sag << " m (" << sag32 << " m at 32), swing tip RMS "
                   << rms * 1000 << " mm");
    CHECK(std::abs(sag / sag32 - 1.0) < 0.15);
    CHECK(rms <= 0.010);
  }
}

TEST_CASE("GPU stiffness: the goals of a free strand keep sum m v", "[gpu][stiffness]") {
  // In float: positions of ~0.3 m round by ~2e-8 m, so a velocity (x - x_old) / h at h = 1/240 s
  // carries ~5e-6 m/s of rounding against the strand's ~0.4 m/s: ~1e-5 per particle, less in
  // the sum of 24. The per-particle weighting the per-region masses replaced moved the momentum
  // by ~2e-2 a step (the CPU reference, in double, keeps it to 1e-13).
  const double drift = test::momentumDrift(makeGpu, 200);
  INFO("largest relative change of the momentum in one step: " << drift);
  CHECK(drift < 1e-4);
}
