// A shot's cache in the process (app/cache_run.h): a render from a cache makes no solver, and the
// frame ranges the command line takes.
#include <unistd.h>

#include <catch2/catch.hpp>

#include <filesystem>

#include "app/cache_run.h"
#include "app/cli.h"
#include "app/headless.h"
#include "app/preset.h"
#include "sim/run/make_solver.h"

using namespace csm;

TEST_CASE("A render from a cache makes no solver, the bake that wrote it made one",
          "[cache][quick]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("csm_shot_cache_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  SceneSetup scene;
  scene.preset = defaultPreset();
  scene.preset.scene.hairstyle.strands = 60;
  scene.source = "<test>";
  Options bake;
  bake.headless = true;
  bake.quiet = true;
  bake.solver = "cpu";
  bake.frames = 4;
  bake.noRender = true;
  bake.bake = (dir / "cache").string();
  const long before = solversMade();
  REQUIRE(runHeadless(bake, scene) == 0);
  CHECK(solversMade() == before + 1);  // so that the count below can see a solver made

  Options draw;
  draw.headless = true;
  draw.quiet = true;
  draw.fromCache = bake.bake;
  draw.firstFrame = 3;
  draw.frames = 4;
  draw.width = 64;
  draw.height = 36;
  draw.outDir = (dir / "frames").string();
  draw.sets = {{"hairstyle.strands", "60"}};
  REQUIRE(runFromCache(draw) == 0);
  CHECK(solversMade() == before + 1);
  CHECK(fs::is_regular_file(dir / "frames" / "frame_00003.png"));
  CHECK(fs::is_regular_file(dir / "frames" / "frame_00004.png"));
  CHECK_FALSE(fs::exists(dir / "frames" / "frame_00002.png"));
  fs::remove_all(dir);
}

TEST_CASE("Frame ranges: N and A-B taken, the rest refused saying why", "[cache][quick]") {
  long first = 0, last = 0;
  std::string error;
  REQUIRE(parseFrameRange("60", first, last, &error));
  CHECK((first == 1 && last == 60));
  REQUIRE(parseFrameRange("31-45", first, last, &error));
  CHECK((first == 31 && last == 45));
  REQUIRE(parseFrameRange("7-7", first, last, &error));
  CHECK((first == 7 && last == 7));
  CHECK_FALSE(parseFrameRange("45-31", first, last, &error));
  CHECK(error == "--frames 45-31: the first frame is after the last");
  CHECK_FALSE(parseFrameRange("0-10", first, last, &error));
  CHECK(error == "--frames 0-10: frames count from 1");
  for (const char* bad : {"", "-5", "a-b", "3-", "3-4-5", "1.5", "10-x"}) {
    INFO(bad);
    CHECK_FALSE(parseFrameRange(bad, first, last, &error));
  }
}
