// The headless frame loop on the real GL driver: without --metrics or outputs it reads nothing
// of the hair back, only a sample of a few numbers every tenth frame for the NaN check.
#include <catch2/catch.hpp>

#include <filesystem>

#include "app/headless.h"
#include "app/preset.h"
#include "gl/fence.h"
#include "tests/gpu/gl_fixture.h"

using namespace csm;

namespace {

SceneSetup smallDefault(int strands) {
  SceneSetup scene;
  scene.preset = defaultPreset();
  scene.preset.scene.hairstyle.strands = strands;
  scene.source = "<test>";
  return scene;
}

Options headlessOptions(long frames) {
  Options o;
  o.headless = true;
  o.frames = frames;
  o.solver = "gpu";
  o.quiet = true;
  return o;
}

}  // namespace

TEST_CASE("headless without --metrics reads nothing back per frame", "[gpu][headless]") {
  test::glContext();
  const SceneSetup scene = smallDefault(300);
  const long frames = 60;
  gl::resetReadbackStats();
  REQUIRE(runHeadless(headlessOptions(frames), scene) == 0);
  const gl::ReadbackStats quiet = gl::readbackStats();
  // One position buffer of this scene is ~3,600 particles x 16 bytes; a sample is two uvec4
  // per 256 particles and the counters.
  const uint64_t positionBytes = 3600 * 16;
  INFO("reads " << quiet.reads << ", bytes " << quiet.bytes << ", blocking waits " << quiet.waits);
  CHECK(quiet.reads <= uint64_t(frames / 10 + 1));
  CHECK(quiet.bytes < positionBytes / 4);

  // The same run with --metrics samples every frame: the count above does see reads.
  Options withMetrics = headlessOptions(frames);
  withMetrics.metrics = (std::filesystem::temp_directory_path() / "csm_headless_m.json").string();
  withMetrics.noRender = true;
  gl::resetReadbackStats();
  REQUIRE(runHeadless(withMetrics, scene) == 0);
  CHECK(gl::readbackStats().reads >= uint64_t(frames));
  std::filesystem::remove(withMetrics.metrics);
  test::glContext();
}
