// The follower pass (render/follower_pass.h) on the real driver: the followers it makes each frame
// are the CPU's (sim/groom/followers.h) to a float's rounding, with either solver driving the
// guides, and every drawn strand is drawn.
#include <algorithm>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "render/renderer_probe.h"
#include "sim/groom/followers.h"
#include "tests/gpu/render_test_scene.h"

using namespace csm;

namespace {

// The renderer's followers of the last frame against the CPU's from the same guides: the largest
// distance between them (m).
float passAgainstCpu(test::RenderScene& scene) {
  Simulation& sim = scene.sim();
  const FollowerBinding& b = *sim.followers();
  const std::vector<glm::vec4> gpu = RendererProbe(scene.renderer())
                                         .followerPass()
                                         .positions()
                                         .download<glm::vec4>(b.drawn.pointCount());
  std::vector<glm::vec4> guides, cpu;
  sim.readPositions(guides);
  sim.drawnPositions(guides, cpu);
  REQUIRE(cpu.size() == gpu.size());
  float worst = 0.0f;
  for (std::size_t i = 0; i < cpu.size(); ++i)
    worst = std::max(worst, glm::length(glm::vec3(cpu[i]) - glm::vec3(gpu[i])));
  return worst;
}

}  // namespace

TEST_CASE("the follower pass makes the CPU's followers, driven by either solver",
          "[followers][quick]") {
  Preset preset = test::presetConfig("default.json", 600);
  preset.scene.hairstyle.guides = 60;
  preset.view.render.children = 0;
  for (const char* solver : {"cpu", "gpu"}) {
    INFO(solver);
    test::glContext();
    std::string error;
    auto sim = std::make_unique<Simulation>(makeSolver(solver, &error));
    REQUIRE(sim->load(preset.scene, std::string(CSM_SOURCE_DIR) + "/presets", &error));
    test::RenderScene scene(preset, 0, std::move(sim));
    for (int f = 0; f < 8; ++f) scene.sim().stepFrame();
    scene.render(160, 90);
    CHECK(scene.renderer().drawnStrands() == 600);
    CHECK(RendererProbe(scene.renderer()).followerPass().drawnPoints() ==
          scene.sim().followers()->drawn.pointCount());
    CHECK(passAgainstCpu(scene) < 2e-5f);
  }
}

TEST_CASE("guides drawn alone: hairstyle.guides = 0 draws the groom as simulated",
          "[followers][quick]") {
  Preset preset = test::presetConfig("default.json", 300);
  preset.view.render.children = 0;
  preset.scene.hairstyle.guides = 0;
  test::RenderScene all(preset, 1);
  CHECK(!all.sim().followers());
  all.render(160, 90);
  CHECK(all.renderer().drawnStrands() == 300);
  preset.scene.hairstyle.guides = 30;
  test::RenderScene guided(preset, 1);
  guided.render(160, 90);
  CHECK(guided.sim().counts().strands == 30);
  CHECK(guided.renderer().drawnStrands() == 300);
}

TEST_CASE("render.show_guides draws the guides alone, highlighted", "[followers][quick]") {
  Preset preset = test::presetConfig("default.json", 300);
  preset.view.render.children = 0;
  preset.scene.hairstyle.guides = 30;
  test::RenderScene scene(preset, 1);
  // Orange pixels: red well over green, green well over blue.
  auto orange = [](const test::Image& image) {
    int n = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const std::uint8_t* p = image.at(x, y);
        n += p[0] > 120 && p[0] > p[1] + 40 && p[1] > p[2] + 30;
      }
    return n;
  };
  const int before = orange(scene.render(160, 90));
  CHECK(scene.renderer().drawnStrands() == 300);
  Preset guides = preset;
  guides.view.render.showGuides = true;
  const int after = orange(scene.render(160, 90, &guides));
  CHECK(scene.renderer().drawnStrands() == 30);
  CHECK(after > before + 20);
}

TEST_CASE("interactive quality with no extra strands draws the guides standing in for followers",
          "[followers][quick]") {
  Preset preset = test::presetConfig("default.json", 300);
  preset.view.render.children = 2;
  preset.scene.hairstyle.guides = 30;
  test::RenderScene scene(preset, 1);
  auto followersRan = [&] {
    for (const StageTime& s : scene.renderer().stageTimes())
      if (s.name == "followers") return true;
    return false;
  };
  scene.renderer().setSynchronousTiming(true);
  DrawAmount amount;
  scene.render(160, 90, nullptr, true, amount);
  CHECK(scene.renderer().drawnStrands() == 900);  // 300 strands and their 600 children
  CHECK(followersRan());
  amount.extra = 0.0f;
  scene.render(160, 90, nullptr, true, amount);
  CHECK(scene.renderer().drawnStrands() == 30);  // the guides, no children
  CHECK_FALSE(followersRan());
  amount.strands = 0.5f;
  scene.render(160, 90, nullptr, true, amount);
  CHECK(scene.renderer().drawnStrands() == 15);
  amount.extra = 0.5f;
  scene.render(160, 90, nullptr, true, amount);
  // Half of the 30 simulated strands and of half the 870 others: 233 of the 300 followers.
  CHECK(scene.renderer().drawnStrands() == 233);
  CHECK(followersRan());
}

TEST_CASE("interactive quality with no extra strands draws no children", "[render][quick]") {
  Preset preset = test::presetConfig("default.json", 300);
  preset.view.render.children = 4;
  test::RenderScene scene(preset, 1);
  DrawAmount amount;
  amount.extra = 0.0f;
  scene.render(160, 90, nullptr, true, amount);
  CHECK(scene.renderer().drawnStrands() == 300);  // the simulated strands, as with no children
  amount.extra = 0.5f;
  scene.render(160, 90, nullptr, true, amount);
  CHECK(scene.renderer().drawnStrands() == 900);  // and half the 1,200 children: 2 a strand
  amount.strands = 0.3f;
  amount.extra = 0.0f;
  scene.render(160, 90, nullptr, true, amount);
  CHECK(scene.renderer().drawnStrands() == 90);
}
