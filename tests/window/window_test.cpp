// The viewer in a real window (run under Xvfb by run_xvfb.sh): presets, live edits through the
// same setter the panels call, screenshots of what the window shows, broken presets, NaN.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <thread>

#include <unistd.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <imgui.h>
#include <png.h>

#include "app/camera_control.h"
#include "app/panels.h"
#include "app/viewer.h"
#include "app/viewer_presets.h"
#include "tests/window/viewer_probe.h"
#include "gl/shader_source.h"
#include "sim/solver/cpu_solver.h"
#include "tests/test_solvers.h"
#include "sim/groom/cyhair.h"
#include "sim/param/sim_params.h"
#include "app/preset.h"

using namespace csm;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = CSM_SOURCE_DIR;

// CSM_WINDOW_TEST_OUT=DIR keeps the screenshots there (for a look, or as CI artifacts).
fs::path tempDir() {
  const char* keep = std::getenv("CSM_WINDOW_TEST_OUT");
  const fs::path dir =
      keep && *keep ? fs::path(keep)
                    : fs::temp_directory_path() / ("csm_window_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir;
}

void removeTemp(const fs::path& dir) {
  const char* keep = std::getenv("CSM_WINDOW_TEST_OUT");
  if (!keep || !*keep) fs::remove_all(dir);
}

// frameLimit: the simulation stops at that frame (and again after a resume before it).
std::unique_ptr<Viewer> makeViewer(SolverByName factory = {}, long frameLimit = -1) {
  ViewerOptions o;
  o.width = 1280;
  o.height = 720;
  o.vsync = false;
  o.quiet = true;
  o.paced = false;  // as fast as it goes
  o.frameLimit = frameLimit;
  o.makeSolver = std::move(factory);
  std::string error;
  std::unique_ptr<Viewer> v = Viewer::create(o, &error);
  INFO(error);
  REQUIRE(v);
  return v;
}

using Clock = std::chrono::steady_clock;

void runFrames(Viewer& v, int n) {
  for (int i = 0; i < n; ++i) v.runFrame();
}

// UI frames until the simulation, on its own thread, has stepped `n` frames more (or can go
// no further: paused, stopped on NaN).
void runSimFrames(Viewer& v, long n) {
  REQUIRE(v.session().sync());
  const long target = v.session().simFrame().frame + n;
  const auto deadline = Clock::now() + std::chrono::minutes(2);
  while (v.session().simFrame().frame < target && !v.session().simFrame().idle &&
         Clock::now() < deadline) {
    v.runFrame();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  REQUIRE((v.session().simFrame().frame >= target || v.session().simFrame().idle));
}

// A screenshot of the first frame that shows every change made so far.
Image screenshot(Viewer& v, const fs::path& path) {
  v.requestScreenshot(path.string());
  const auto deadline = Clock::now() + std::chrono::minutes(2);
  while (ViewerProbe(v).screenshotPending() && Clock::now() < deadline) v.runFrame();
  REQUIRE(v.lastScreenshotPath() == path.string());
  return ViewerProbe(v).lastScreenshot();
}

std::array<int, 3> rgb8(const ImVec4& c) {
  return {int(std::lround(c.x * 255.0f)), int(std::lround(c.y * 255.0f)),
          int(std::lround(c.z * 255.0f))};
}

bool near(const uint8_t* p, const std::array<int, 3>& c, int tolerance) {
  for (int i = 0; i < 3; ++i)
    if (std::abs(int(p[i]) - c[i]) > tolerance) return false;
  return true;
}

// Share of pixels in [x0, x1) x [y0, y1) that match `pred`.
template <class Pred>
double share(const Image& img, int x0, int y0, int x1, int y1, Pred pred) {
  long hits = 0, all = 0;
  for (int y = std::max(0, y0); y < std::min(img.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(img.width, x1); ++x, ++all)
      if (pred(img.pixel(x, y))) ++hits;
  return all ? double(hits) / double(all) : 0.0;
}

// The most common colour of a region: the background, where the region shows no scene.
std::array<int, 3> dominant(const Image& img, int x0, int y0, int x1, int y1) {
  std::map<std::array<int, 3>, long> count;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const uint8_t* p = img.pixel(x, y);
      ++count[{p[0], p[1], p[2]}];
    }
  return std::max_element(count.begin(), count.end(),
                          [](auto& a, auto& b) { return a.second < b.second; })
      ->first;
}

// Reads a PNG back with libpng: width and height, 0 on failure.
std::pair<int, int> pngSize(const fs::path& path) {
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return {0, 0};
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  std::pair<int, int> size{0, 0};
  if (!setjmp(png_jmpbuf(png))) {
    png_init_io(png, f);
    png_read_info(png, info);
    size = {int(png_get_image_width(png, info)), int(png_get_image_height(png, info))};
  }
  png_destroy_read_struct(&png, &info, nullptr);
  std::fclose(f);
  return size;
}

}  // namespace

TEST_CASE(
    "window: a preset runs, strand count and wind change live, the screenshot shows "
    "hair and panels",
    "[window]") {
  const fs::path dir = tempDir();
  std::unique_ptr<Viewer> v = makeViewer();
  REQUIRE(v->session().loadPreset((kSource / "presets/short_shake.json").string()));
  REQUIRE(v->session().sync());
  REQUIRE(v->session().presetErrors().empty());
  runSimFrames(*v, 3);
  const size_t before = v->session().simFrame().strands;
  CHECK(before == 6000);
  const CameraConfig camera = v->session().document().current().view.camera;
  // Paused, so the clock can be compared across the change.
  v->session().controls().setPaused(true);
  REQUIRE(v->session().sync());
  const double t = v->session().simFrame().time;

  // The same setter the panels call (Viewer::applyConfig), by parameter name.
  REQUIRE(v->session().setParam("hairstyle.strands", "1500"));
  REQUIRE(v->session().setParam("wind.strength", "8"));
  REQUIRE(v->session().setParam("wind.direction", "0,0,1"));
  // Strand count is live within a frame: no restart, same camera, same clock.
  REQUIRE(v->session().sync());
  CHECK(v->session().simFrame().strands == 1500);
  CHECK(v->session().simFrame().config.hairstyle.strands == 1500);
  CHECK(v->session().simFrame().config.wind.strength == 8.0f);
  const CameraConfig& now = v->session().document().current().view.camera;
  CHECK((now.target == camera.target && now.distance == camera.distance && now.yaw == camera.yaw &&
         now.pitch == camera.pitch && now.fov == camera.fov));
  CHECK(v->session().simFrame().time == Approx(t));
  const auto changed = v->session().document().modifiedKeys();
  CHECK(std::find(changed.begin(), changed.end(), "hairstyle.strands") != changed.end());
  CHECK(std::find(changed.begin(), changed.end(), "wind.strength") != changed.end());

  v->session().controls().setPaused(false);
  runSimFrames(*v, 10);
  CHECK(v->session().simFrame().strands == 1500);
  CHECK(v->session().simFrame().particles > 1500);
  REQUIRE(v->session().simFrame().sample.has_value());
  CHECK(v->session().simFrame().sample->frame > 0);
  CHECK(std::isfinite(v->session().simFrame().sample->accuracy.maxStrain));
  CHECK_FALSE(v->session().controls().nanStopped());

  const fs::path shot = dir / "viewer.png";
  const Image img = screenshot(*v, shot);
  REQUIRE(img.width == 1280);
  REQUIRE(img.height == 720);
  CHECK(pngSize(shot) == std::make_pair(1280, 720));

  // Hair: the middle of the window differs from the background (the most common colour of a
  // strip above the head, between the panels).
  const auto background = dominant(img, 500, 2, 800, 20);
  const double hair =
      share(img, 540, 260, 740, 460, [&](const uint8_t* p) { return !near(p, background, 24); });
  INFO("background " << background[0] << "," << background[1] << "," << background[2]
                     << "; share of non-background pixels in the middle " << hair);
  CHECK(hair > 0.05);

  // Hair, not just the head: paused, the same frame with one strand instead of 1500 differs
  // in the scene area between the panels.
  v->session().controls().setPaused(true);
  runFrames(*v, 1);
  const Image withHair = screenshot(*v, dir / "with_hair.png");
  REQUIRE(v->session().setParam("hairstyle.strands", "1"));
  const Image bald = screenshot(*v, dir / "one_strand.png");
  const double diff = share(withHair, 430, 60, 880, 640, [&](const uint8_t* p) {
    const size_t at = size_t(p - withHair.rgb.data());
    const uint8_t* q = bald.rgb.data() + at;
    return std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]) > 30;
  });
  INFO("share of the scene area that changes when the hair goes: " << diff);
  CHECK(diff > 0.03);

  // Panels: the title bars of Parameters (top left) and Stats (top right, under Help folded
  // to its title bar: panelLayout) in ImGui's colours.
  const ImGuiStyle& style = ImGui::GetStyle();
  const auto title = rgb8(style.Colors[ImGuiCol_TitleBg]);
  const auto titleActive = rgb8(style.Colors[ImGuiCol_TitleBgActive]);
  auto isTitle = [&](const uint8_t* p) { return near(p, title, 3) || near(p, titleActive, 3); };
  const double left = share(img, 200, 2, 380, 14, isTitle);
  const double right = share(img, img.width - 120, 26, img.width - 30, 36, isTitle);
  INFO("title bar share: left " << left << ", right " << right);
  CHECK(left > 0.9);
  CHECK(right > 0.9);
  // The parameter panel's body is ImGui's dark window background, not the scene.
  const auto body = rgb8(style.Colors[ImGuiCol_WindowBg]);
  CHECK(share(img, 2, 20, 400, 700, [&](const uint8_t* p) { return near(p, body, 12); }) > 0.3);

  removeTemp(dir);
}

TEST_CASE("window: a broken preset shows its messages and the scene keeps running", "[window]") {
  const fs::path dir = tempDir();
  std::unique_ptr<Viewer> v = makeViewer();
  REQUIRE(v->session().loadPreset((kSource / "presets/short_shake.json").string()));
  REQUIRE(v->session().sync());
  REQUIRE(v->session().setParam("hairstyle.strands", "500"));
  const std::string opened = v->session().document().path();
  const fs::path broken = dir / "broken.json";
  std::ofstream(broken) << R"({"sim": {"substeps": 0}, "wind": {"strenght": 3}})";

  CHECK_FALSE(v->session().loadPreset(broken.string()));
  REQUIRE(v->session().presetErrors().size() >= 2);
  std::string all;
  for (const std::string& m : v->session().presetErrors()) all += m + "\n";
  INFO(all);
  CHECK(all.find("sim.substeps") != std::string::npos);
  CHECK(all.find("strenght") != std::string::npos);
  CHECK(all.find("broken.json") != std::string::npos);
  CHECK(v->session().document().path() == opened);
  REQUIRE(v->session().sync());
  CHECK(v->session().simFrame().strands == 500);

  runSimFrames(*v, 2);
  const Image img = screenshot(*v, dir / "broken.png");
  // The "Preset problems" window has a red title bar.
  const std::array<int, 3> red = {int(0.75f * 255 + 0.5f), int(0.08f * 255 + 0.5f),
                                  int(0.08f * 255 + 0.5f)};
  const std::array<int, 3> redInactive = {int(0.6f * 255 + 0.5f), int(0.05f * 255 + 0.5f),
                                          int(0.05f * 255 + 0.5f)};
  CHECK(share(img, 0, 0, img.width, img.height, [&](const uint8_t* p) {
          return near(p, red, 3) || near(p, redInactive, 3);
        }) > 0.002);

  // A value the panel could hold but the scene cannot: refused with a message, nothing lost.
  CHECK_FALSE(v->session().setParam("hairstyle.min_particles", "40"));
  REQUIRE(v->session().sync());
  CHECK(v->session().simFrame().config.hairstyle.minParticles == 5);
  CHECK(v->session().document().current().scene.hairstyle.minParticles == 5);
  v->session().dismissPresetErrors();
  CHECK(v->session().presetErrors().empty());
  removeTemp(dir);
}

TEST_CASE("window: NaN from the simulation pauses the viewer and says so", "[window]") {
  const fs::path dir = tempDir();
  std::unique_ptr<Viewer> v = makeViewer([](const std::string&, std::string*) {
    return std::unique_ptr<Solver>(new test::NanAfter(4));
  });
  Preset c = defaultPreset();
  c.scene.hairstyle.strands = 300;
  std::string error;
  REQUIRE(v->session().open(c, "", "", &error));
  // The samples come a few frames late: the thread stops within a few frames of the bad one.
  REQUIRE(v->session().waitForSimFrame(40));
  REQUIRE(v->session().controls().nanStopped());
  CHECK(v->session().controls().paused());
  CHECK(v->session().simFrame().nanFrame >= 4);
  const long frame = v->session().simFrame().frame;
  CHECK(frame < 40);
  runFrames(*v, 3);
  REQUIRE(v->session().sync());
  CHECK(v->session().simFrame().frame == frame);  // stopped: no garbage steps

  const Image img = screenshot(*v, dir / "nan.png");
  // The red banner at the top centre.
  const std::array<int, 3> bannerish = {178, 13, 13};
  CHECK(share(img, img.width / 2 - 200, 0, img.width / 2 + 200, 120,
              [&](const uint8_t* p) { return near(p, bannerish, 25); }) > 0.05);

  v->session().controls().resetHair();
  CHECK_FALSE(v->session().controls().nanStopped());
  removeTemp(dir);
}

TEST_CASE("window: a shader that fails to reload keeps the old program and shows the log",
          "[window]") {
  const fs::path dir = tempDir();
  const fs::path shaders = dir / "shaders";
  fs::remove_all(shaders);
  fs::copy(kSource / "shaders", shaders, fs::copy_options::recursive);
  gl::setShaderDirectory(shaders);
  std::unique_ptr<Viewer> v = makeViewer();
  Preset c = defaultPreset();
  c.scene.hairstyle.strands = 400;
  std::string error;
  REQUIRE(v->session().open(c, "", "", &error));
  REQUIRE(ViewerProbe(*v).sceneView().hasRenderer());
  v->session().controls().setPaused(true);
  runFrames(*v, 2);
  const Image before = screenshot(*v, dir / "before_reload.png");

  std::ofstream(shaders / "render/hair.frag", std::ios::app) << "\nthis is not GLSL\n";
  CHECK_FALSE(ViewerProbe(*v).reloadShaders());
  CHECK(ViewerProbe(*v).sceneView().shaderReloadFailed());
  CHECK(ViewerProbe(*v).sceneView().shaderLog().find("hair.frag") != std::string::npos);
  // The old programs still draw: the scene area below the log window is as it was.
  const Image after = screenshot(*v, dir / "after_failed_reload.png");
  const double changed = share(before, 430, 380, 880, 640, [&](const uint8_t* p) {
    const uint8_t* q = after.rgb.data() + (p - before.rgb.data());
    return std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]) > 30;
  });
  INFO("share of the scene area changed by the failed reload " << changed);
  CHECK(changed < 0.02);

  fs::copy_file(kSource / "shaders/render/hair.frag", shaders / "render/hair.frag",
                fs::copy_options::overwrite_existing);
  CHECK(ViewerProbe(*v).reloadShaders());
  CHECK_FALSE(ViewerProbe(*v).sceneView().shaderReloadFailed());
  v.reset();
  gl::setShaderDirectory({});
  removeTemp(dir);
}

TEST_CASE("panels: the parameter tree holds every parameter once", "[window][panels]") {
  size_t count = 0;
  std::function<void(const ParamGroup&)> walk = [&](const ParamGroup& g) {
    count += g.params.size();
    for (const ParamGroup& c : g.children) walk(c);
  };
  for (const ParamGroup& g : paramGroups()) walk(g);
  CHECK(count == params().size());
  const auto sim = std::find_if(paramGroups().begin(), paramGroups().end(),
                                [](const ParamGroup& g) { return g.name == "Simulation"; });
  REQUIRE(sim != paramGroups().end());
  CHECK(std::any_of(sim->children.begin(), sim->children.end(),
                    [](const ParamGroup& g) { return g.name == "Collision"; }));
}

TEST_CASE("panels: presets are found from the source tree", "[window][panels]") {
  const auto dirs = presetDirectories((kSource / "presets/default.json").string());
  REQUIRE_FALSE(dirs.empty());
  const auto files = listPresets(dirs);
  CHECK(std::any_of(files.begin(), files.end(),
                    [](const fs::path& p) { return p.filename() == "paper_fig1_straight.json"; }));
}

TEST_CASE("panels: the layout tiles the window, no panel over another, the middle left free",
          "[window][panels]") {
  struct Size {
    float width, height, font;
  };
  // The default window (1280x720) and smaller and larger ones, at the viewer's font and at
  // Dear ImGui's own (13 pixels, where DejaVu Sans is missing); 2560x1440 unfolds Help.
  const std::vector<Size> sizes = {{1280, 720, 15}, {1600, 900, 15},  {1920, 1080, 15},
                                   {1024, 640, 15}, {2560, 1440, 15}, {1280, 720, 13},
                                   {1024, 640, 13}};
  for (const Size& s : sizes) {
    INFO(s.width << "x" << s.height << ", font " << s.font);
    const PanelLayout l = panelLayout(s.width, s.height, s.font);
    const std::vector<std::pair<const char*, PanelRect>> rects = {{"parameters", l.parameters},
                                                                  {"stats", l.stats},
                                                                  {"help", l.help},
                                                                  {"timeline", l.timeline},
                                                                  {"view", l.view}};
    for (const auto& [name, r] : rects) {
      INFO(name << " at " << r.x << ", " << r.y << ", " << r.width << " x " << r.height);
      CHECK(r.width > 0.0f);
      CHECK(r.height > 0.0f);
      CHECK(r.x >= 0.0f);
      CHECK(r.y >= 0.0f);
      CHECK(r.x + r.width <= s.width);
      CHECK(r.y + r.height <= s.height);
    }
    for (size_t i = 0; i < rects.size(); ++i)
      for (size_t j = 0; j < i; ++j) {
        const PanelRect &a = rects[i].second, &b = rects[j].second;
        INFO(rects[i].first << " and " << rects[j].first);
        const bool apart = a.x + a.width <= b.x || b.x + b.width <= a.x || a.y + a.height <= b.y ||
                           b.y + b.height <= a.y;
        CHECK(apart);
      }
    // The hair's part: the window's centre, at least a third of its width and half its height.
    CHECK(l.view.x < 0.5f * s.width);
    CHECK(l.view.x + l.view.width > 0.5f * s.width);
    CHECK(l.view.y < 0.5f * s.height);
    CHECK(l.view.y + l.view.height > 0.5f * s.height);
    CHECK(l.view.width >= s.width / 3.0f);
    CHECK(l.view.height >= 0.5f * s.height);
    // Help's title bar at least; unfolded only where the window is large.
    CHECK(l.help.height >= s.font + 6.0f);
    CHECK(l.helpOpen == (s.width >= 2560.0f));
  }
}

TEST_CASE("camera control: orbit, zoom and head drag stay in range and keep the pivot",
          "[window][camera]") {
  CameraConfig cam;
  orbitCamera(cam, 0.0f, 10000.0f);
  CHECK(cam.pitch == Approx(findParam("camera.pitch")->max));
  orbitCamera(cam, 100.0f, 0.0f);
  CHECK(cam.yaw == Approx(CameraConfig{}.yaw - 100.0f * kOrbitDegreesPerPixel));
  zoomCamera(cam, 1000.0f);
  CHECK(cam.distance == Approx(findParam("camera.distance")->min));

  Config c = defaultPreset().scene;
  const std::shared_ptr<const HeadModel> head = HeadModel::require(c);
  frameHead(cam, c, *head, Pose{});
  // The scalp grown by the longest strand is centred and fits the vertical field of view.
  const float reach = c.head.spheres[0].radius + c.hairstyle.lengthMax;
  CHECK(glm::length(cam.target - c.head.spheres[0].center) < 0.05f);
  CHECK(cam.distance * std::sin(glm::radians(cam.fov) * 0.5f) >= reach);
  CHECK(cam.distance * std::sin(glm::radians(cam.fov) * 0.5f) < 1.5f * reach);
  // Where the head is now: a head moved up 1 m moves the target with it.
  Pose up;
  up.translation = glm::dvec3(0.0, 1.0, 0.0);
  CameraConfig moved = cam;
  frameHead(moved, c, *head, up);
  CHECK(moved.target.y == Approx(cam.target.y + 1.0f));

  const Pose turned = dragHead(Pose{}, cam, c.head, 80.0f, -40.0f);
  const glm::dvec3 pivot(c.head.pivot);
  CHECK(glm::length(turned.apply(pivot) - pivot) < 1e-9);
  CHECK(glm::length(turned.apply(glm::dvec3(0.0, 0.1, 0.0)) - glm::dvec3(0.0, 0.1, 0.0)) > 0.01);
}

TEST_CASE("window: the UI runs while a frame of simulation does not end", "[window]") {
  auto gate = std::make_shared<test::GatedSolver::Gate>();
  // Opened at the end whatever happens (declared after the viewer, so destroyed before
  // it), or the viewer's destructor would wait for the frame forever.
  struct Opener {
    test::GatedSolver::Gate& g;
    ~Opener() { test::allow(g, 1000000); }
  };
  std::unique_ptr<Viewer> v = makeViewer([gate](const std::string&, std::string*) {
    return std::unique_ptr<Solver>(new test::GatedSolver(gate));
  });
  Preset c = defaultPreset();
  c.scene.hairstyle.strands = 200;
  std::string error;
  const Opener opener{*gate};
  REQUIRE(v->session().open(c, "", "", &error));
  // The thread is now inside its first frame, which does not end until the gate opens: the
  // window still draws, takes edits and moves the camera.
  const auto deadline = Clock::now() + std::chrono::seconds(30);
  while (gate->started < 1 && Clock::now() < deadline) std::this_thread::yield();
  REQUIRE(gate->started == 1);
  const long drawn = v->framesDrawn();
  runFrames(*v, 20);
  CHECK(v->framesDrawn() == drawn + 20);
  CHECK(v->session().simFrame().frame == 0);
  REQUIRE(v->session().setParam("camera.yaw", "75"));
  REQUIRE(v->session().setParam("wind.strength", "3"));  // queued for the thread, between frames
  runFrames(*v, 2);
  CHECK(v->session().document().current().view.camera.yaw == 75.0f);
  CHECK(v->session().simFrame().config.wind.strength !=
        3.0f);  // not yet applied: the frame runs on

  // The frame ends: the edit is applied before the next one, and the view shows it.
  test::allow(*gate, 3);
  REQUIRE(v->session().waitForSimFrame(3));
  CHECK(v->session().simFrame().frame == 3);
  CHECK(v->session().simFrame().config.wind.strength == 3.0f);
}

TEST_CASE("window: interactive quality while simulating, full when still and for screenshots",
          "[window]") {
  const fs::path dir = tempDir();
  std::unique_ptr<Viewer> v = makeViewer();
  Preset c = defaultPreset();
  c.scene.hairstyle.strands = 400;
  c.view.render.children = 3;
  std::string error;
  REQUIRE(v->session().open(c, "", "", &error));
  REQUIRE(v->session().document().current().view.render.interactive);
  runSimFrames(*v, 3);
  runFrames(*v, 1);
  CHECK(ViewerProbe(*v).sceneView().lastQuality() == DrawQuality::Interactive);
  // A share of the strands: render.interactive_amount of the 400 simulated and of as many of
  // their 1,200 children as the frame budget allows (llvmpipe's frames are over 33 ms: none).
  const double amount = v->session().document().current().view.render.interactiveAmount;
  CHECK(double(v->stats().drawnStrands) <= amount * 1600.0 + 1.0);
  CHECK(double(v->stats().drawnStrands) >= amount * 400.0 - 1.0);
  // No budget: the share of all 1,600, from the frame after.
  REQUIRE(v->session().setParam("render.interactive_budget_ms", "0"));
  runSimFrames(*v, 2);
  runFrames(*v, 2);
  CHECK(ViewerProbe(*v).sceneView().lastQuality() == DrawQuality::Interactive);
  CHECK(double(v->stats().drawnStrands) >= 0.5 * amount * 1600.0);
  CHECK(double(v->stats().drawnStrands) < 0.6 * 1600.0);

  // A screenshot is drawn in full even while the hair runs.
  screenshot(*v, dir / "running.png");
  CHECK(ViewerProbe(*v).sceneView().lastQuality() == DrawQuality::Full);
  CHECK(v->stats().drawnStrands == 1600);

  // Paused and still: full quality, and then no new picture while nothing changes.
  v->session().controls().setPaused(true);
  REQUIRE(v->session().sync());
  runFrames(*v, 2);
  CHECK(ViewerProbe(*v).sceneView().lastQuality() == DrawQuality::Full);
  const long scenes = ViewerProbe(*v).sceneView().scenesDrawn();
  runFrames(*v, 5);
  CHECK(ViewerProbe(*v).sceneView().scenesDrawn() == scenes);
  // A change of the look draws again.
  REQUIRE(v->session().setParam("render.strand_width", "2.5"));
  runFrames(*v, 1);
  CHECK(ViewerProbe(*v).sceneView().scenesDrawn() == scenes + 1);

  // Interactive quality off: full while running too.
  REQUIRE(v->session().setParam("render.interactive", "false"));
  v->session().controls().setPaused(false);
  runSimFrames(*v, 2);
  runFrames(*v, 1);
  CHECK(ViewerProbe(*v).sceneView().lastQuality() == DrawQuality::Full);
  removeTemp(dir);
}

// Pixels of the scene's middle that differ between two screenshots (the panels and banners
// around it differ with the frame's text).
double sceneDifference(const Image& a, const Image& b) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  const int x0 = a.width * 33 / 100, x1 = a.width * 67 / 100;
  const int y0 = a.height * 12 / 100, y1 = a.height * 68 / 100;
  long differ = 0, all = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x, ++all) {
      const uint8_t *p = a.pixel(x, y), *q = b.pixel(x, y);
      differ += p[0] != q[0] || p[1] != q[1] || p[2] != q[2];
    }
  return double(differ) / double(all);
}

TEST_CASE("window: the timeline records, scrubs, plays and resumes; the pixels show the frame",
          "[window][timeline]") {
  const fs::path dir = tempDir();
  std::unique_ptr<Viewer> v = makeViewer({}, 40);
  std::string error;
  Preset c = defaultPreset();
  c.scene.hairstyle.strands = 400;
  c.scene.head.amplitude = 30.0f;  // a nod that moves the hair between frames
  c.scene.head.frequency = 1.5f;
  REQUIRE(v->session().open(c, "", "", &error));
  REQUIRE(v->session().waitForSimFrame(40));
  REQUIRE(v->session().sync());
  const TimelineStatus& t = v->session().simFrame().timeline;
  REQUIRE(v->session().simFrame().frame == 40);
  CHECK(t.first == 0);
  CHECK(t.last == 40);
  CHECK(t.shown == -1);
  CHECK(t.bytes > 0);
  CHECK(t.bytes <= t.budget);
  const Image live = screenshot(*v, dir / "live40.png");

  // Scrubbed back to frame 12: that frame's picture, the simulation paused at 40.
  v->session().controls().showRecorded(12);
  REQUIRE(v->session().sync());
  CHECK(v->session().simFrame().timeline.shown == 12);
  CHECK(v->session().simFrame().frame == 12);
  CHECK(v->session().simFrame().timeline.live == 40);
  const Image at12 = screenshot(*v, dir / "recorded12.png");
  CHECK(sceneDifference(at12, live) > 0.01);
  // Frame 40 from the recording is the live frame 40, pixel for pixel.
  v->session().controls().showRecorded(40);
  REQUIRE(v->session().sync());
  CHECK(sceneDifference(screenshot(*v, dir / "recorded40.png"), live) == 0.0);

  // Played back from frame 12 at real time (1/60 s a frame), not looping: it moves on, no
  // faster than real time (however slowly the UI draws: llvmpipe may take most of a second a
  // frame), and stops at the last frame.
  v->session().controls().setLoopRecording(false);
  v->session().controls().showRecorded(12);
  REQUIRE(v->session().sync());
  const auto playStart = Clock::now();
  v->session().controls().playRecording(true);
  CHECK(v->session().controls().playingRecording());
  while (v->session().simFrame().timeline.shown <= 15 &&
         Clock::now() < playStart + std::chrono::minutes(1)) {
    v->runFrame();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const double elapsed = std::chrono::duration<double>(Clock::now() - playStart).count();
  const long played = v->session().simFrame().timeline.shown;
  INFO("after " << elapsed << " s of playback: frame " << played);
  CHECK(played > 15);
  CHECK(played <= 12 + long(elapsed * 60.0) + 1);
  // Looping, from near the end: it comes round to the start.
  v->session().controls().setLoopRecording(true);
  v->session().controls().showRecorded(38);
  REQUIRE(v->session().sync());
  v->session().controls().playRecording(true);
  const auto loopStart = Clock::now();
  bool wrapped = false;
  while (!wrapped && Clock::now() < loopStart + std::chrono::minutes(1)) {
    v->runFrame();
    wrapped = v->session().simFrame().timeline.shown < 38;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  CHECK(wrapped);
  CHECK(v->session().controls().playingRecording());
  v->session().controls().playRecording(false);

  // Resumed from frame 20 and run on to the limit (40): the frames as recorded, the same
  // picture at 40.
  v->session().controls().showRecorded(20);
  REQUIRE(v->session().sync());
  const Image at20 = screenshot(*v, dir / "recorded20.png");
  v->session().controls().resumeFrom(20);
  REQUIRE(v->session().sync());
  CHECK(v->session().simFrame().timeline.shown == -1);
  CHECK(v->session().simFrame().frame == 20);
  CHECK(v->session().simFrame().timeline.last == 20);
  CHECK(v->session().controls().paused());
  CHECK(sceneDifference(screenshot(*v, dir / "resumed20.png"), at20) == 0.0);
  bool said = false;
  for (const ViewerMessage& m : v->session().messages())
    said |= m.text.rfind("resumed from frame 20", 0) == 0;
  CHECK(said);
  v->session().controls().setPaused(false);
  REQUIRE(v->session().waitForSimFrame(40));
  REQUIRE(v->session().sync());
  CHECK(v->session().simFrame().frame == 40);
  CHECK(v->session().simFrame().timeline.last == 40);
  CHECK(sceneDifference(screenshot(*v, dir / "again40.png"), live) == 0.0);

  // A bake: 10 frames as fast as they go, recorded, then paused (the limit lifted by a reset
  // would start again at 0: bake from the resumed 20 instead).
  v->session().controls().resumeFrom(20);
  REQUIRE(v->session().sync());
  v->session().controls().bake(10.0 / 60.0);
  REQUIRE(v->session().waitForSimFrame(30));
  REQUIRE(v->session().sync());
  CHECK(v->session().simFrame().frame == 30);
  CHECK(v->session().simFrame().timeline.last == 30);
  CHECK(v->session().simFrame().timeline.bakeLeft == 0);
  CHECK(v->session().simFrame().idle);
  removeTemp(dir);
}

TEST_CASE("window: A/B shows two settings over the same frames; the recording exports as .hair",
          "[window][timeline]") {
  const fs::path dir = tempDir();
  std::unique_ptr<Viewer> v = makeViewer({}, 30);
  std::string error;
  Preset c = defaultPreset();
  c.scene.hairstyle.strands = 400;
  REQUIRE(v->session().open(c, "", "", &error));
  REQUIRE(v->session().waitForSimFrame(30));
  REQUIRE(v->session().sync());
  v->session().controls().keepAsA();
  REQUIRE(v->session().sync());
  CHECK(v->session().simFrame().timeline.aFirst == 0);
  CHECK(v->session().simFrame().timeline.aLast == 30);
  // A counts against the one budget: the recording and A within it.
  CHECK(v->session().simFrame().timeline.aBytes > 0);
  CHECK(v->session().simFrame().timeline.bytes + v->session().simFrame().timeline.aBytes <=
        v->session().simFrame().timeline.budget);
  v->session().controls().showRecorded(30);
  REQUIRE(v->session().sync());
  const Image a30 = screenshot(*v, dir / "a30.png");

  // B: a strong wind, simulated again over A's frames.
  REQUIRE(v->session().setParam("wind.strength", "14", &error));
  CHECK(v->session().controls().keysChangedSinceA() ==
        std::vector<std::string_view>{"wind.strength"});
  v->session().controls().rerunFromA();
  REQUIRE(v->session().waitForSimFrame(30));
  REQUIRE(v->session().sync());
  CHECK(v->session().simFrame().timeline.last == 30);
  CHECK(v->session().simFrame().timeline.bytes + v->session().simFrame().timeline.aBytes <=
        v->session().simFrame().timeline.budget);
  v->session().controls().showRecorded(30);
  REQUIRE(v->session().sync());
  CHECK_FALSE(v->session().simFrame().timeline.showingA);
  const Image b30 = screenshot(*v, dir / "b30.png");
  CHECK(sceneDifference(a30, b30) > 0.01);
  // The toggle: A's frame 30 again, pixel for pixel.
  v->session().controls().showA(true);
  REQUIRE(v->session().sync());
  CHECK(v->session().simFrame().timeline.showingA);
  CHECK(sceneDifference(screenshot(*v, dir / "a30_again.png"), a30) == 0.0);
  v->session().controls().showA(false);
  REQUIRE(v->session().sync());
  CHECK(sceneDifference(screenshot(*v, dir / "b30_again.png"), b30) == 0.0);

  // The recording (B) out as cyHair, one file a frame, the same strands in each.
  const fs::path seq = dir / "seq";
  v->session().controls().exportRecorded(seq.string(), 0, 30);
  REQUIRE(v->session().sync());
  size_t files = 0;
  for (const auto& e : fs::directory_iterator(seq)) files += e.path().extension() == ".hair";
  CHECK(files == 31);
  const io::GroomReadResult last = io::readCyHair((seq / "frame_00031.hair").string());
  REQUIRE(last.groom);
  CHECK(last.groom->strandCount() == 400);
  bool said = false;
  for (const ViewerMessage& m : v->session().messages())
    said |= m.text == "wrote frames 0-30 as 31 cyHair files into " + seq.string();
  CHECK(said);

  // A regrown groom: A cannot be run again on it, and the viewer says so.
  REQUIRE(v->session().setParam("hairstyle.strands", "300", &error));
  REQUIRE(v->session().sync());
  v->session().controls().rerunFromA();
  CHECK(v->session().messages().back().text.rfind("cannot run B: A was recorded on another groom",
                                                  0) == 0);
  removeTemp(dir);
}

TEST_CASE("window: a groom file imported while the window runs shows its progress, then clears",
          "[window][import]") {
  const fs::path dir = tempDir();
  // 10,000 strands x 100 points: long enough an import for the UI to draw a few frames of it
  // (20,000, until the suite's time was cut, took 25-60 s of this machine; 10,000 take 2-4).
  const int strands = 10000;
  Groom big;
  std::vector<glm::vec3> strand(100);
  for (int s = 0; s < strands; ++s) {
    const float a = 2.399963f * float(s), z = 1.0f - 0.9f * (float(s) + 0.5f) / float(strands);
    const float r = std::sqrt(1.0f - z * z);
    const glm::vec3 n(r * std::cos(a), z, r * std::sin(a));
    for (int i = 0; i < 100; ++i)
      strand[size_t(i)] =
          0.1f * n + glm::vec3(0.0f, -0.002f * float(i), 0.0f) + 0.001f * float(i) * n;
    big.addStrand(strand);
  }
  const std::string file = (dir / "big.hair").string();
  REQUIRE(csm::io::writeCyHair(file, big, nullptr));

  std::unique_ptr<Viewer> v = makeViewer();
  Preset c = defaultPreset();
  c.scene.hairstyle.strands = 300;
  std::string error;
  REQUIRE(v->session().open(c, "", "", &error));
  runSimFrames(*v, 1);
  CHECK(v->session().importStatus().stage.empty());
  REQUIRE(v->session().setParam("hairstyle.strands", "1000000"));
  REQUIRE(v->session().setParam("hairstyle.file", file));
  // The window keeps drawing while the thread imports; the banner's stages come and go.
  std::vector<std::string> stages;
  const auto deadline = Clock::now() + std::chrono::minutes(2);
  while (v->session().simFrame().strands != size_t(strands) && Clock::now() < deadline) {
    v->runFrame();
    const std::string stage = v->session().importStatus().stage;
    if (!stage.empty() && (stages.empty() || stages.back() != stage)) stages.push_back(stage);
  }
  INFO("stages seen:" << [&] {
    std::string s;
    for (const std::string& x : stages) s += " " + x;
    return s;
  }());
  REQUIRE(v->session().simFrame().strands == size_t(strands));
  CHECK(!stages.empty());
  CHECK(v->session().importStatus().stage.empty());
  fs::remove_all(dir);
}
