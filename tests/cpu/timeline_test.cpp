// The timeline on its own (sim/run/timeline.h): no thread, no GL, the CPU reference.
#include <filesystem>
#include <memory>
#include <string>

#include <catch2/catch.hpp>

#include "sim/groom/cyhair.h"
#include "sim/run/simulation.h"
#include "sim/run/timeline.h"
#include "sim/solver/cpu_solver.h"
#include "test_scenes.h"

namespace csm {
namespace {

std::unique_ptr<Simulation> loaded(const Config& c) {
  auto sim = std::make_unique<Simulation>(std::make_unique<CpuSolver>());
  std::string error;
  REQUIRE(sim->load(c, "", &error));
  return sim;
}

}  // namespace

TEST_CASE("Timeline: records, shows, resumes, bakes, keeps A and exports, with no thread or GL",
          "[timeline][quick]") {
  Config c = test::smallScene(20);
  c.head.motion = HeadMotion::Shake;
  std::unique_ptr<Simulation> sim = loaded(c);
  Timeline t;
  t.restarted(*sim);
  for (int f = 0; f < 10; ++f) {
    sim->stepFrame();
    CHECK_FALSE(t.stepped(*sim));  // no bake: never asks to pause
  }
  TimelineStatus s = t.status(*sim);
  CHECK(s.recording);
  CHECK(s.first == 0);
  CHECK(s.last == 10);
  CHECK(s.live == 10);
  CHECK(s.shown == -1);
  CHECK(s.bytes > 0);
  CHECK(s.bytes <= s.budget);

  // A recorded frame on show; a frame not recorded is live again.
  CHECK(t.show(4));
  CHECK(t.showing());
  REQUIRE(t.shownFrame());
  CHECK(t.shownFrame()->frame == 4);
  CHECK(t.status(*sim).shown == 4);
  CHECK_FALSE(t.show(40));
  CHECK(t.status(*sim).shown == -1);

  // Resuming from frame 4 puts the simulation there, nothing on show; stepping on records again.
  std::string message;
  REQUIRE(t.resume(*sim, 4, &message));
  CHECK_THAT(message, Catch::StartsWith("resumed from frame 4"));
  CHECK(sim->frame() == 4);
  CHECK_FALSE(t.showing());
  CHECK_FALSE(t.resume(*sim, 99, &message));
  CHECK_THAT(message, Catch::StartsWith("cannot resume: "));

  // A as the recording is now; the next frames differ from it once a parameter changes.
  t.keepAsA(*sim);
  t.setBudget(t.budget());
  s = t.status(*sim);
  CHECK(s.aFirst == 0);
  CHECK(s.aLast == 4);
  CHECK(s.aBytes > 0);
  CHECK(s.bytes + s.aBytes <= s.budget);
  REQUIRE(s.aConfig);
  CHECK(s.aGeneration == sim->generation());

  // A bake of 3 frames: the third asks for the pause.
  CHECK(t.bake(3));
  CHECK(t.baking());
  CHECK(t.status(*sim).bakeTotal == 3);
  bool paused = false;
  for (int f = 0; f < 3; ++f) {
    CHECK_FALSE(paused);
    sim->stepFrame();
    paused = t.stepped(*sim);
  }
  CHECK(paused);
  CHECK_FALSE(t.baking());
  CHECK(t.status(*sim).last == 7);
  CHECK_FALSE(t.bake(0));

  // A's frame on show at the frame number shown, when asked for and where A has it.
  t.showA(true);
  CHECK(t.show(2));
  bool isA = false;
  REQUIRE(t.shownFrame(&isA));
  CHECK(isA);
  CHECK(t.status(*sim).showingA);
  CHECK(t.show(6));  // A ends at 4: the recording's frame
  REQUIRE(t.shownFrame(&isA));
  CHECK_FALSE(isA);
  t.show(-1);

  // Export: the recorded frames as cyHair files, the groom's strands in each.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("csm_timeline_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  REQUIRE(t.exportFrames(*sim, dir.string(), 5, 7, &message));
  CHECK_THAT(message, Catch::StartsWith("wrote frames 5-7 as 3 cyHair files"));
  const io::GroomReadResult read = io::readCyHair((dir / "frame_00003.hair").string());
  REQUIRE(read.groom);
  CHECK(read.groom->strandCount() == sim->groom().strandCount());
  CHECK_FALSE(t.exportFrames(*sim, dir.string(), 5, 9, &message));
  CHECK_THAT(message, Catch::Contains("frame 8 is not recorded"));
  std::filesystem::remove_all(dir);

  // Off: stepping records nothing; a restart starts the recording again from its frame.
  t.setRecording(false);
  sim->stepFrame();
  t.stepped(*sim);
  CHECK(t.status(*sim).last == 7);
  t.setRecording(true);
  sim->reset();
  t.restarted(*sim);
  s = t.status(*sim);
  CHECK(s.first == 0);
  CHECK(s.last == 0);
}

}  // namespace csm
