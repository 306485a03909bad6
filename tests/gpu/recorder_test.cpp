// The timeline's recording (sim/run/frame_recording.h) on both solvers (the GPU one on the real GL
// driver, llvmpipe where there is no GPU): resuming from a recorded frame gives the frames
// that were recorded after it, bit for bit; the cache keeps within its memory budget.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "gl/fence.h"
#include "sim/solver/cpu_probe.h"
#include "sim/gpu/gpu_probe.h"
#include "sim/solver/cpu_solver.h"
#include "sim/run/frame_recording.h"
#include "sim/run/simulation.h"
#include "tests/cpu/test_scenes.h"
#include "tests/gpu/gpu_solver_fixture.h"
#include "sim/verify/solver_head.h"

using namespace csm;

namespace {

std::unique_ptr<Solver> solverNamed(const std::string& name) {
  if (name == "gpu") return test::gpuSolver();
  return std::make_unique<CpuSolver>();
}

// Strand contacts, a gusty wind and a nodding head: every part of the state in play.
Config busyScene() {
  Config c = test::smallScene(60);
  c.collision.mode = CollisionMode::Strands;
  c.collision.headShape = HeadShape::Sdf;
  c.head.motion = HeadMotion::Nod;
  c.head.amplitude = 30.0f;
  c.head.frequency = 1.0f;
  c.wind.strength = 4.0f;
  c.wind.gusts = 0.5f;
  return c;
}

std::vector<glm::vec3> positionsOf(Simulation& sim) {
  std::vector<glm::vec4> x;
  sim.readPositions(x);
  return std::vector<glm::vec3>(x.begin(), x.end());
}

}  // namespace

TEST_CASE("FrameRecording: record 120 frames, resume from 60: the frames after it as recorded",
          "[recorder][gpu]") {
  const std::string name = GENERATE(std::string("cpu"), std::string("gpu"));
  INFO("solver " << name);
  Simulation sim(solverNamed(name));
  std::string error;
  REQUIRE(sim.load(busyScene(), ".", &error));
  FrameRecording recorder;  // keyframes every 30 frames
  recorder.record(sim);
  std::vector<std::vector<glm::vec3>> recorded{positionsOf(sim)};
  for (int f = 1; f <= 120; ++f) {
    sim.stepFrame();
    recorder.record(sim);
    recorded.push_back(positionsOf(sim));
  }
  recorder.flush();  // the last frames' copies may still be on their way
  CHECK(recorder.inFlight() == 0);
  REQUIRE(recorder.firstFrame() == 0);
  REQUIRE(recorder.lastFrame() == 120);
  CHECK(recorder.keyframeCount() == 5);  // 0, 30, 60, 90, 120
  CHECK(*recorder.positions(77) == recorded[77]);

  for (long from : {60L, 75L}) {  // a keyframe, and 15 frames past one
    INFO("resumed from frame " << from);
    double mismatch = -1.0;
    REQUIRE(recorder.resume(sim, from, &error, &mismatch));
    CHECK(mismatch == 0.0);
    CHECK(sim.frame() == from);
    CHECK(recorder.lastFrame() == from);  // the frames after it are recorded again
    size_t differ = 0;
    for (long f = from + 1; f <= 120; ++f) {
      sim.stepFrame();
      recorder.record(sim);
      differ += positionsOf(sim) != recorded[size_t(f)];
    }
    recorder.flush();
    CHECK(differ == 0);
    CHECK(recorder.lastFrame() == 120);
    CHECK(recorder.firstFrame() == 0);
  }
  // A change made after the recording: resuming replays the recorded frames with what they
  // ran with, and goes on with the change.
  Config windier = sim.config();
  windier.wind.strength = 9.0f;
  REQUIRE(sim.setConfig(windier, &error));
  double mismatch = -1.0;
  REQUIRE(recorder.resume(sim, 45, &error, &mismatch));
  CHECK(mismatch == 0.0);
  CHECK(sim.config().wind.strength == 9.0f);
  sim.stepFrame();
  CHECK(positionsOf(sim) != recorded[46]);
  // A frame not recorded is refused, saying which are.
  CHECK_FALSE(recorder.resume(sim, 121, &error));
  CHECK(error == "frame 121 is not recorded (frames 0-45 are)");
}

TEST_CASE("FrameRecording: the cache never exceeds its memory budget, and every frame kept resumes",
          "[recorder][gpu]") {
  const std::string name = GENERATE(std::string("cpu"), std::string("gpu"));
  INFO("solver " << name);
  Simulation sim(solverNamed(name));
  std::string error;
  REQUIRE(sim.load(busyScene(), ".", &error));
  // The size of a span of 10 frames, measured on a first recording.
  FrameRecording probe({size_t(1) << 30, 10});
  for (int f = 0; f < 10; ++f) {
    sim.stepFrame();
    probe.record(sim);
  }
  probe.flush();
  const size_t span = probe.bytes();
  // Room for three and a half spans.
  FrameRecording recorder({span * 7 / 2, 10});
  size_t most = 0;
  for (int f = 0; f < 200; ++f) {
    sim.stepFrame();
    recorder.record(sim);
    most = std::max(most, recorder.bytes());
  }
  recorder.flush();
  most = std::max(most, recorder.bytes());
  INFO("span " << span << " B, budget " << recorder.options().budgetBytes << " B, most held "
               << most << " B, " << recorder.frameCount() << " frames kept");
  CHECK(most <= recorder.options().budgetBytes);
  CHECK(recorder.frameCount() >= 25);  // whole spans go, oldest first
  CHECK(recorder.frameCount() <= 35);
  CHECK(recorder.lastFrame() == sim.frame());
  CHECK(recorder.refused() == 0);
  // The first frame kept is a keyframe: it resumes, with no mismatch.
  const long first = recorder.firstFrame();
  const std::vector<glm::vec3> kept = *recorder.positions(first + 3);
  double mismatch = -1.0;
  REQUIRE(recorder.resume(sim, first + 3, &error, &mismatch));
  CHECK(mismatch == 0.0);
  CHECK(positionsOf(sim) == kept);
  CHECK_FALSE(recorder.resume(sim, first - 1, &error));

  // A budget shrunk below the recording drops the oldest spans at once.
  recorder.setBudget(span * 3 / 2);
  CHECK(recorder.bytes() <= span * 3 / 2);
  CHECK(!recorder.empty());
  // A budget smaller than one keyframe keeps nothing and counts what it refused.
  FrameRecording tiny({1024, 10});
  sim.stepFrame();
  tiny.record(sim);
  tiny.flush();
  CHECK(tiny.empty());
  CHECK(tiny.bytes() == 0);
  CHECK(tiny.refused() == 1);
}

TEST_CASE("FrameRecording: on the GPU nothing waits for a frame's copy, keyframes included",
          "[recorder][gpu]") {
  Simulation sim(test::gpuSolver());
  std::string error;
  Config c = busyScene();
  c.collision.mode = CollisionMode::Head;  // no candidate search (it reads its counters back)
  REQUIRE(sim.load(c, ".", &error));
  FrameRecording recorder({size_t(1) << 30, 10});
  recorder.record(sim);
  gl::resetReadbackStats();
  size_t mostInFlight = 0;
  for (int f = 1; f <= 40; ++f) {
    sim.stepFrame();
    recorder.record(sim);
    mostInFlight = std::max(mostInFlight, recorder.inFlight());
  }
  const gl::ReadbackStats stats = gl::readbackStats();
  INFO(stats.reads << " reads, " << stats.bytes << " bytes, " << stats.waits << " waits; "
                   << mostInFlight << " copies in flight at most");
  // Each copy is read once its fence has passed: no read waited for the GPU. (How many are in
  // flight depends on how far the CPU runs ahead: none on llvmpipe, which computes as it is
  // asked; all 40 on an H100, the loop issuing frames faster than the GPU runs them.)
  CHECK(stats.waits == 0);
  CHECK(recorder.lastFrame() == 40 - long(recorder.inFlight()));
  // Once the GPU is done, collecting takes them all without waiting.
  sim.diagnostics().finish();
  recorder.collect();
  CHECK(recorder.inFlight() == 0);
  CHECK(recorder.lastFrame() == 40);
  CHECK(gl::readbackStats().waits == 0);
  CHECK(recorder.keyframeCount() == 5);  // 0, 10, 20, 30, 40: their states came the same way
  double mismatch = -1.0;
  REQUIRE(recorder.resume(sim, 25, &error, &mismatch));
  CHECK(mismatch == 0.0);
}

TEST_CASE("FrameRecording: a regrown groom starts the recording again, its states are refused",
          "[recorder]") {
  Simulation sim(std::make_unique<CpuSolver>());
  std::string error;
  Config c = test::smallScene(30);
  REQUIRE(sim.load(c, ".", &error));
  FrameRecording recorder;
  for (int f = 0; f < 5; ++f) {
    sim.stepFrame();
    recorder.record(sim);
  }
  SimulationState before;
  sim.save(before);
  c.hairstyle.strands = 40;  // regrows
  REQUIRE(sim.setConfig(c, &error));
  CHECK_FALSE(sim.restore(before, &error));
  CHECK_THAT(error, Catch::Contains("another groom"));
  sim.stepFrame();
  recorder.record(sim);
  CHECK(recorder.frameCount() == 1);
  CHECK(recorder.firstFrame() == sim.frame());
}

TEST_CASE("Solvers: the first frame after a restore counts no crossings against another state",
          "[recorder][gpu]") {
  // Crossings are sign changes against the last frame's list. After a restore the list kept
  // is of the state the solver had before it (here 10 frames of wind later): counted against
  // it, pairs that were never near each other across a frame counted as crossings. As after
  // a reset, there is nothing to count against; the frame after counts again.
  const std::string name = GENERATE(std::string("cpu"), std::string("gpu"));
  INFO("solver " << name);
  Config c = busyScene();
  c.hairstyle.strands = 300;
  const Groom g = test::growFor(c);
  std::unique_ptr<Solver> solver = solverNamed(name);
  auto contacts = [&] {
    return name == "gpu" ? GpuProbe(static_cast<GpuSolver&>(*solver)).readContactStats()
                         : CpuProbe(static_cast<CpuSolver&>(*solver)).contactStats();
  };
  resetWithHead(*solver, g, c, Pose{});
  for (int f = 0; f < 10; ++f) solver->stepFrame(Pose{}, Pose{});
  SavedState saved;
  solver->state().save(saved);
  solver->stepFrame(Pose{}, Pose{});
  const uint64_t along = contacts().crossings;  // as the run went on
  for (int f = 0; f < 9; ++f) solver->stepFrame(Pose{}, Pose{});
  std::string error;
  REQUIRE(solver->state().restore(saved, &error));
  solver->stepFrame(Pose{}, Pose{});
  INFO(along << " crossings in the frame after the saved one as the run went on");
  CHECK(contacts().crossings == 0);
  CHECK(contacts().candidates > 0);
  solver->stepFrame(Pose{}, Pose{});
  uint64_t later = contacts().crossings;
  for (int f = 0; f < 5; ++f) {
    solver->stepFrame(Pose{}, Pose{});
    later += contacts().crossings;
  }
  CHECK(later > 0);
}
