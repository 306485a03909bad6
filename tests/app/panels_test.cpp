// The panels (app/panels.h) drawn by Dear ImGui with no window and no renderer, their buttons
// pressed as a user presses them, and what they ask recorded by a fake PanelRequests: the
// scene's requests are written down, the simulation's commands go to a real session's controls
// (the CPU solver), so that a press shows in the simulation too.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <imgui.h>
#include <imgui_internal.h>

#include "app/panels.h"
#include "app/preset.h"
#include "app/viewer_session.h"
#include "tests/app/app_fixture.h"

using namespace csm;

namespace {

// Records the requests the panels make of the viewer; the simulation's commands go to the
// session's controls.
class FakeRequests final : public PanelRequests {
 public:
  explicit FakeRequests(ViewerSession& session) : session_(session) {}
  SimControls& controls() override { return session_.controls(); }
  Preset& editedPreset() override { return session_.editedPreset(); }
  bool applyConfig(const Preset& next) override {
    asked.push_back("applyConfig");
    applied = next;
    return true;
  }
  bool loadPreset(const std::string& path) override { return ask("loadPreset " + path); }
  bool save() override { return ask("save"); }
  bool saveAs(const std::string& path) override { return ask("saveAs " + path); }
  void revert() override { ask("revert"); }
  void frameHead() override { ask("frameHead"); }
  void resetView() override { ask("resetView"); }
  void resetHead() override { ask("resetHead"); }
  bool reloadShaders() override { return ask("reloadShaders"); }
  void screenshot() override { ask("screenshot"); }
  void dismissPresetErrors() override { ask("dismissPresetErrors"); }
  void dismissShaderLog() override { ask("dismissShaderLog"); }
  void setVsync(bool on) override { ask(on ? "vsync on" : "vsync off"); }

  std::vector<std::string> asked;
  Preset applied;

 private:
  bool ask(const std::string& what) {
    asked.push_back(what);
    return true;
  }
  ViewerSession& session_;
};

// Dear ImGui without a backend: a display of 1280 x 720, the default font's atlas built; frames
// drawn and never rendered.
class Headless {
 public:
  Headless() {
    context_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(1280.0f, 720.0f);
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  }
  ~Headless() { ImGui::DestroyContext(context_); }

  void frame(const PanelView& view, PanelRequests& ask, PanelState& state) {
    ImGui::NewFrame();
    drawPanels(view, ask, state);
    ImGui::Render();
  }
  // Presses the button `label` of the window `window` (at the window's root) in the next frame.
  void press(const char* window, const char* label) {
    ImGuiWindow* w = ImGui::FindWindowByName(window);
    REQUIRE(w != nullptr);
    ImGui::ActivateItem(w->GetID(label));
  }

 private:
  ImGuiContext* context_;
};

// A session running the default preset's 60 strands, the panels over it with a fake, drawn a
// frame at a time.
struct Rig {
  explicit Rig(long frameLimit, const Preset& preset = test::smallPreset(60))
      : session(test::makeSession(frameLimit)), fake(*session) {
    std::string error;
    REQUIRE(session->open(preset, "", "", &error));
  }
  // The session's events and latest frame, then the panels over them.
  void frame() {
    session->update();
    const ViewerSession& s = *session;
    imgui.frame(PanelView{.frame = s.simFrame(),
                          .document = s.document(),
                          .stats = stats,
                          .messages = s.messages(),
                          .presetErrors = s.presetErrors(),
                          .presetErrorsNote = s.presetErrorsNote(),
                          .picture = picture,
                          .import = s.importStatus(),
                          .renderer = renderer,
                          .loading = s.loading(),
                          .vsync = false},
                fake, state);
  }
  std::unique_ptr<ViewerSession> session;
  FakeRequests fake;
  PanelState state;
  ViewerStats stats;
  const PictureStatus picture;
  const std::string renderer = "none";
  Headless imgui;
};

bool asked(const FakeRequests& fake, const std::string& what) {
  for (const std::string& a : fake.asked)
    if (a == what) return true;
  return false;
}

}  // namespace

TEST_CASE("Panels: drawn with nothing pressed, they ask nothing", "[app][panels][quick]") {
  Rig rig(10);
  REQUIRE(rig.session->waitForSimFrame(10));
  for (int f = 0; f < 3; ++f) rig.frame();
  CHECK(rig.fake.asked.empty());
  CHECK(ImGui::FindWindowByName("Parameters") != nullptr);
  CHECK(ImGui::FindWindowByName("Timeline") != nullptr);
  CHECK(ImGui::FindWindowByName("Stats") != nullptr);
}

TEST_CASE("Panels: the buttons ask the viewer and command the simulation", "[app][panels][quick]") {
  Rig rig(-1);
  ViewerSession* s = rig.session.get();
  Headless& imgui = rig.imgui;
  const FakeRequests& fake = rig.fake;
  auto frame = [&] { rig.frame(); };
  REQUIRE(s->waitForSimFrame(3));
  frame();

  // Pause: the simulation stops where it is.
  imgui.press("Parameters", "Pause");
  frame();
  CHECK(s->controls().paused());
  REQUIRE(s->sync());
  const long at = s->simFrame().frame;
  REQUIRE(s->sync());
  CHECK(s->simFrame().frame == at);
  // Step: one frame more, paused.
  imgui.press("Parameters", "Step");
  frame();
  REQUIRE(s->waitForSimFrame(at + 1));
  CHECK(s->simFrame().frame == at + 1);
  CHECK(s->controls().paused());
  // Run again (the same button, now labelled so).
  imgui.press("Parameters", "Run");
  frame();
  CHECK_FALSE(s->controls().paused());

  // The viewer's own requests.
  for (const char* button : {"Frame head", "Reset view", "Undo head drag", "Screenshot"}) {
    imgui.press("Parameters", button);
    frame();
  }
  CHECK(asked(fake, "frameHead"));
  CHECK(asked(fake, "resetView"));
  CHECK(asked(fake, "resetHead"));
  CHECK(asked(fake, "screenshot"));
  // The presets' section: save and revert.
  imgui.press("Parameters", "Save");
  frame();
  imgui.press("Parameters", "Revert");
  frame();
  CHECK(asked(fake, "save"));
  CHECK(asked(fake, "revert"));

  // Reset hair: the simulation from rest, time 0 (paused first, so that a machine's speed cannot
  // run it past `at` again before it is looked at).
  imgui.press("Parameters", "Pause");
  frame();
  REQUIRE(s->sync());
  imgui.press("Parameters", "Reset hair");
  frame();
  REQUIRE(s->sync());
  CHECK(s->simFrame().frame < at + 1);
}

TEST_CASE("Panels: the timeline's buttons scrub, keep A and go live again",
          "[app][panels][timeline][quick]") {
  Rig rig(12);
  ViewerSession* s = rig.session.get();
  Headless& imgui = rig.imgui;
  auto frame = [&] { rig.frame(); };
  REQUIRE(s->waitForSimFrame(12));
  REQUIRE(s->sync());
  frame();
  REQUIRE(s->simFrame().timeline.last == 12);
  // The first recorded frame, on show.
  imgui.press("Timeline", "|<");
  frame();
  REQUIRE(s->sync());
  CHECK(s->simFrame().timeline.shown == 0);
  imgui.press("Timeline", ">|");
  frame();
  REQUIRE(s->sync());
  CHECK(s->simFrame().timeline.shown == 12);
  imgui.press("Timeline", "Keep as A");
  frame();
  REQUIRE(s->sync());
  CHECK(s->simFrame().timeline.aLast == 12);
  imgui.press("Timeline", "Live");
  frame();
  REQUIRE(s->sync());
  CHECK(s->simFrame().timeline.shown == -1);
}

TEST_CASE("Panels: the Motion panel opens a clip, records it and scrubs it by its frames",
          "[app][panels][motion]") {
  Preset preset = test::smallPreset(40);
  Rig rig(400, preset);
  ViewerSession* s = rig.session.get();
  Headless& imgui = rig.imgui;
  REQUIRE(s->waitForSimFrame(2));
  rig.frame();
  // No clip yet: the panel says what moves the head.
  ImGuiWindow* motion = ImGui::FindWindowByName("Motion");
  REQUIRE(motion != nullptr);
  CHECK(motion->Collapsed);
  CHECK_FALSE(s->simFrame().clip);
  ImGui::SetWindowCollapsed("Motion", false);
  rig.frame();
  // A clip's path, opened: the preset's motion.clip, applied.
  rig.state.clipPath = std::string(CSM_CLIP_DIR) + "/jump.bvh";
  imgui.press("Motion", "Open");
  rig.frame();
  REQUIRE(asked(rig.fake, "applyConfig"));
  CHECK(rig.fake.applied.scene.motion.clip == rig.state.clipPath);
  REQUIRE(s->applyConfig(rig.fake.applied));
  REQUIRE(s->sync());
  REQUIRE(s->simFrame().clip);
  const MotionClip& clip = *s->simFrame().clip;
  CHECK(clip.facts().unit == "cm");
  CHECK(clip.facts().frames == 91);
  // Recorded whole from its first frame: the clip's 3 s, 180 frames, then paused.
  imgui.press("Motion", "Record the clip");
  rig.frame();
  REQUIRE(s->waitForSimFrame(181));
  REQUIRE(s->sync());
  rig.frame();
  CHECK(s->simFrame().timeline.last >= 181);
  // A recorded frame on show is the clip's there: the head where the clip put it.
  for (long f : {30L, 66L, 120L}) {
    s->controls().showRecorded(f);
    REQUIRE(s->sync());
    rig.frame();
    const double t = double(f) * double(preset.scene.sim.dt);
    CHECK(s->simFrame().time == Approx(t));
    const Pose want = clip.sample(t, true, false).head;
    CHECK(glm::length(s->simFrame().headPose.translation - want.translation) < 1e-6);
    CHECK(clip.frameAt(s->simFrame().time, true) == int(std::floor(t * 30.0 + 1e-6)));
  }
  // The jump lifts the head: the recording's frames differ where the clip does.
  s->controls().showRecorded(60);
  REQUIRE(s->sync());
  const double before = s->simFrame().headPose.translation.y;
  s->controls().showRecorded(90);
  REQUIRE(s->sync());
  CHECK(s->simFrame().headPose.translation.y > before + 0.2);
}
