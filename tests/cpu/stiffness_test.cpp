// The calibrated stiffness model on the CPU reference (tests/stiffness_cases.h holds the
// scenes; tests/gpu/gpu_stiffness_test.cpp runs the same on the GPU solver): the hairstyle does
// not change with density, substeps, frame rate or particle count, the goals conserve momentum,
// and the window coefficient the model is calibrated with is what this solver measures.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim/cpu/cpu_solver.h"
#include "sim/stiffness.h"
#include "tests/stiffness_cases.h"

using namespace csm;

namespace {

std::unique_ptr<Solver> makeCpu() {
  return std::make_unique<CpuSolver>();
}

}  // namespace

TEST_CASE("the window coefficient c_w of the calibration is what the solver measures") {
  for (int w = 1; w <= 16; ++w) {
    const double measured = measureWindowCoefficient(w);
    INFO("w = " << w << ": measured " << measured << ", table " << windowCoefficient(w));
    CHECK(std::abs(windowCoefficient(w) / measured - 1.0) < 2e-3);
  }
  // Beyond the table, (1 + 2/w) / 45.
  for (int w : {20, 32}) {
    const double measured = measureWindowCoefficient(w);
    INFO("w = " << w << ": measured " << measured << ", formula " << windowCoefficient(w));
    CHECK(std::abs(windowCoefficient(w) / measured - 1.0) < 3e-3);
  }
}

TEST_CASE("substeps follow the stiffest strand, at least sim.substeps, capped by max_substeps") {
  SimConfig sim;
  sim.dt = 1.0f / 60.0f;
  sim.substeps = 2;
  sim.maxSubsteps = 64;
  // k = 240^2: exactly 4 steps of 1/240 s give alpha = 1.
  FramePlan p = planFrame(sim, 240.0 * 240.0);
  CHECK(p.substeps == 4);
  CHECK_FALSE(p.capped);
  CHECK(stepAlpha(sim, 240.0 * 240.0, p.h) == Approx(1.0));
  CHECK(planFrame(sim, 241.0 * 241.0).substeps == 5);
  sim.substeps = 9;  // a minimum
  CHECK(planFrame(sim, 240.0 * 240.0).substeps == 9);
  CHECK(stepAlpha(sim, 240.0 * 240.0, planFrame(sim, 240.0 * 240.0).h) ==
        Approx((4.0 / 9.0) * (4.0 / 9.0)));
  sim.substeps = 1;
  sim.maxSubsteps = 3;
  p = planFrame(sim, 240.0 * 240.0);
  CHECK(p.substeps == 3);
  CHECK(p.wanted == 4);
  CHECK(p.capped);
  // The paper model takes sim.substeps as it is, and its alpha.
  sim.stiffnessModel = StiffnessModel::Paper;
  sim.substeps = 2;
  sim.stiffness = 0.7f;
  CHECK(planFrame(sim, 1e12).substeps == 2);
  CHECK(stepAlpha(sim, 1e12, 1.0) == Approx(0.7));
}

TEST_CASE("a capped stiffness is said in the solver's stiffness info") {
  Scene s = test::clampedStrand(24);
  s.config.sim.windowLength = 0.005f;  // w = 1: a rate of ~9e7 /s^2, ~160 steps a frame
  s.config.sim.maxSubsteps = 16;
  CpuSolver solver;
  solver.reset(s.groom, s.config, Pose{});
  const StiffnessInfo info = solver.stiffness();
  CHECK(info.plan.capped);
  CHECK(info.plan.substeps == 16);
  CHECK(info.alphaMax == 1.0);
  CHECK(stiffnessWarning(info).find("max_substeps") != std::string::npos);
  s.config.sim.maxSubsteps = 256;
  solver.setConfig(s.config);  // live: no warning any more
  CHECK_FALSE(solver.stiffness().plan.capped);
  CHECK(stiffnessWarning(solver.stiffness()).empty());
}

TEST_CASE("density: the default scene at 5e-6, 1e-4 and 1e-2 kg/m agrees after 1 s") {
  Scene s = test::defaultScene();
  const auto reference = test::runFor(makeCpu, s, 1.0);
  for (float density : {5e-6f, 1e-2f}) {
    s.config.sim.density = density;
    const double rms = test::rmsDistance(test::runFor(makeCpu, s, 1.0), reference);
    INFO("density " << density << ": RMS " << rms << " m from 1e-4 kg/m");
    CHECK(rms < 1e-6);
  }
}

TEST_CASE("substeps: a clamped strand sags the same at 8 to 64 substeps") {
  const double reference = test::clampedSag(makeCpu, 16, 64);
  CHECK(reference > 0.02);  // it does sag: 12 cm of hair, not a rod
  for (int substeps : {8, 16, 32}) {
    const double sag = test::clampedSag(makeCpu, 16, substeps);
    INFO(substeps << " substeps: sag " << sag << " m, 64 substeps: " << reference << " m");
    CHECK(std::abs(sag / reference - 1.0) < 0.02);
  }
}

TEST_CASE("substeps: the nodding default scene converges as the step shrinks") {
  const Scene s = test::defaultScene();
  std::vector<std::vector<glm::vec4>> runs;
  for (int substeps : {8, 16, 32, 64}) {
    Scene n = s;
    n.config.sim.substeps = substeps;
    runs.push_back(test::runFor(makeCpu, n, 1.0));
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

TEST_CASE("frame rate: 30, 60 and 120 frames a second with automatic substeps agree") {
  const double sag60 = test::clampedSag(makeCpu, 16, 1, 1.0 / 60.0);
  Scene s = test::defaultScene();
  s.config.sim.substeps = 1;
  const auto at60 = test::runFor(makeCpu, s, 1.0);
  for (double dt : {1.0 / 30.0, 1.0 / 120.0}) {
    const double sag = test::clampedSag(makeCpu, 16, 1, dt);
    Scene f = s;
    f.config.sim.dt = float(dt);
    const double rms = test::tipRms(s.groom, test::runFor(makeCpu, f, 1.0), at60);
    INFO("dt " << dt << ": sag " << sag << " m (" << sag60 << " at 1/60 s), tip RMS " << rms * 1000
               << " mm");
    CHECK(std::abs(sag / sag60 - 1.0) < 0.02);
    CHECK(rms <= 0.005);
  }
}

TEST_CASE("resolution: 16, 24 and 32 particles on the same strand sag and swing alike") {
  const double sag32 = test::clampedSag(makeCpu, 32);
  const auto swing32 = test::swingTip(makeCpu, 32);
  for (int particles : {16, 24}) {
    const double sag = test::clampedSag(makeCpu, particles);
    const double rms = test::pathRms(test::swingTip(makeCpu, particles), swing32);
    INFO(particles << " particles: sag " << sag << " m (" << sag32 << " m at 32), swing tip RMS "
                   << rms * 1000 << " mm");
    CHECK(std::abs(sag / sag32 - 1.0) < 0.15);
    CHECK(rms <= 0.010);
  }
}

TEST_CASE("resolution: the paper model's window in particles does not hold a strand's sag") {
  // What the calibrated model fixes: w = 4 particles spans half the length at 32 particles
  // that it spans at 16, and the strand is far softer. (Under a weak gravity, so that neither
  // strand simply hangs.)
  auto sag = [](int particles) {
    Scene s = test::clampedStrand(particles);
    s.config.sim.stiffnessModel = StiffnessModel::Paper;
    s.config.sim.stiffnessWindow = 4;
    s.config.sim.gravity = glm::vec3(0.0f, -1.0f, 0.0f);
    s.config.sim.substeps = 4;
    s.config.sim.damping = 10.0f;
    CpuSolver solver;
    SceneRunner run(solver, s);
    run.runTo(2.0);
    return solver.positions().front().y - solver.positions().back().y;
  };
  const double sag16 = sag(16), sag32 = sag(32);
  INFO("paper model: sag " << sag16 << " m at 16 particles, " << sag32 << " m at 32");
  CHECK(sag32 > 2.0 * sag16);
}

TEST_CASE("momentum: the goals of a free strand keep sum m v to 1e-12 per step") {
  const double drift = test::momentumDrift(makeCpu, 200);
  INFO("largest relative change of the momentum in one step: " << drift);
  CHECK(drift < 1e-12);
}
