#include <catch2/catch.hpp>

#include "render/interactive_budget.h"
#include "render/view_params.h"
#include "sim/gpu/gpu_solver.h"
#include "tests/gpu/gl_fixture.h"
#include "tests/gpu/render_test_scene.h"
#include "tests/live_params_check.h"

using namespace csm;

TEST_CASE("every live parameter changes the motion when changed live (GPU)", "[params][live]") {
  test::glContext();
  std::string error;
  std::unique_ptr<GpuSolver> gpu = GpuSolver::create(&error);
  INFO(error);
  REQUIRE(gpu);
  const test::LiveCheck check = test::checkLiveParams(std::move(gpu));
  CHECK(check.tested.size() >= 33);
  INFO("no effect: " << Catch::Detail::stringify(check.noEffect));
  CHECK(check.noEffect.empty());
}

namespace {

bool sameImage(const test::Image& a, const test::Image& b) {
  return a.rgb == b.rgb;
}

}  // namespace

TEST_CASE("every render parameter changes the picture", "[params][render]") {
  Preset preset = test::presetConfig("default.json", 300);
  preset.view.render.shadowMapSize = 512;
  preset.view.render.samples = 1;
  preset.view.render.interactive = true;
  // Simulated through guides, so that the guides' own setting (render.show_guides) shows too.
  preset.scene.hairstyle.guides = 100;
  test::RenderScene scene(preset, 3);
  const int w = 160, h = 120;
  // The interactive settings show in the viewer's interactive amount (its frame budget's share
  // after a frame measured at 20 ms), the others at full quality (captures, a still view).
  auto interactiveOf = [](const RenderConfig& r) {
    DrawAmount a = interactiveAmount(r);
    InteractiveBudget budget;
    budget.measured(20.0, double(r.interactiveBudgetMs));
    a.extra = budget.extra();
    return a;
  };
  auto draw = [&](const Preset& p, bool interactive) {
    return scene.render(w, h, &p, true, interactive ? interactiveOf(p.view.render) : DrawAmount{});
  };
  const test::Image full = draw(preset, false), fast = draw(preset, true);
  test::dumpImage(full, "params_full");
  test::dumpImage(fast, "params_interactive");
  REQUIRE(sameImage(draw(preset, false), full));  // the comparison means something
  REQUIRE(!sameImage(full, fast));

  std::vector<std::string> tested, noEffect;
  auto check = [&](std::string_view key, const std::vector<Preset>& variants, bool interactive) {
    tested.emplace_back(key);
    for (const Preset& v : variants)
      if (!sameImage(draw(v, interactive), interactive ? fast : full)) return;
    noEffect.emplace_back(key);
  };
  // A parameter that does something only on another preset (the children's own settings)
  // is checked on that one: `base` with the parameter applying, and its picture.
  Preset withChildren = preset;
  withChildren.view.render.children = 3;
  const test::Image childPicture = draw(withChildren, false);
  for (const Param<ViewConfig>& p : viewParams()) {
    if (p.effect != Effect::Render) continue;
    const bool own = p.applies(preset.view);
    if (!own) REQUIRE(p.applies(withChildren.view));
    const Preset& base = own ? preset : withChildren;
    std::vector<Preset> variants;
    for (const ViewConfig& v : test::paramVariants(p, base.view)) {
      Preset changed = base;
      changed.view = v;
      variants.push_back(changed);
    }
    if (own) {
      check(p.key, variants, p.group == "Rendering|Interactive");
      continue;
    }
    tested.emplace_back(p.key);
    bool changed = false;
    for (const Preset& v : variants) changed = changed || !sameImage(draw(v, false), childPicture);
    if (!changed) noEffect.emplace_back(p.key);
  }
  for (const Param<Config>& p : simParams()) {
    if (p.effect != Effect::Render) continue;
    std::vector<Preset> variants;
    for (const Config& c : test::paramVariants(p, preset.scene)) {
      Preset changed = preset;
      changed.scene = c;
      variants.push_back(changed);
    }
    check(p.key, variants, false);
  }
  CHECK(tested.size() >= 30);
  INFO("no effect: " << Catch::Detail::stringify(noEffect));
  CHECK(noEffect.empty());
}
