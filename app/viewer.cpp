#include "app/viewer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app/camera_control.h"
#include "app/panels.h"
#include "app/shot_cache.h"
#include "app/window.h"
#include "gl/caps.h"
#include "gl/debug.h"
#include "gl/fence.h"

namespace csm {
namespace {

using Clock = std::chrono::steady_clock;

const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

}  // namespace

// What the panels ask: the scene's requests go to the session, the window's to the viewer.
class Viewer::Requests final : public PanelRequests {
 public:
  explicit Requests(Viewer& v) : v_(v) {}
  SimControls& controls() override { return s().controls(); }
  Preset& editedPreset() override { return s().editedPreset(); }
  bool applyConfig(const Preset& next) override { return s().applyConfig(next); }
  bool loadPreset(const std::string& path) override { return s().loadPreset(path); }
  bool save() override { return s().save(); }
  bool saveAs(const std::string& path) override { return s().saveAs(path); }
  void revert() override { s().revert(); }
  void frameHead() override { s().frameHead(); }
  void resetView() override { s().resetView(); }
  void resetHead() override { s().resetHead(); }
  void dismissPresetErrors() override { s().dismissPresetErrors(); }
  bool reloadShaders() override { return v_.reloadShaders(); }
  void screenshot() override { v_.requestScreenshot(v_.defaultScreenshotName()); }
  void dismissShaderLog() override { v_.view_->dismissShaderLog(); }
  void setVsync(bool on) override { v_.window_->setVsync(on); }

 private:
  ViewerSession& s() { return *v_.session_; }
  Viewer& v_;
};

Viewer::Viewer() = default;

std::unique_ptr<Viewer> Viewer::create(const ViewerOptions& options, std::string* error) {
  std::unique_ptr<Viewer> v(new Viewer());
  v->options_ = options;

  GlfwWindow::Options wo;
  wo.width = options.width;
  wo.height = options.height;
  wo.vsync = options.vsync;
  v->window_ = GlfwWindow::create(wo, error);
  if (!v->window_) return nullptr;
  const bool software = gl::isSoftwareRenderer(v->window_->renderer());
  if (software && options.requireGpu) {
    *error = "--require-gpu: the window's OpenGL (" + v->window_->renderer() +
             ") is a software renderer, not a GPU";
    return nullptr;
  }

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // layout comes from the code, not a stray imgui.ini in the cwd
  ImGui::StyleColorsDark();
  if (std::filesystem::exists(kFontPath)) io.Fonts->AddFontFromFileTTF(kFontPath, 15.0f);
  ImGui_ImplGlfw_InitForOpenGL(v->window_->handle(), true);
  ImGui_ImplOpenGL3_Init("#version 430 core");
  v->imguiReady_ = true;

  v->view_ = std::make_unique<SceneView>();
  SessionOptions so;
  so.solver = options.solver;
  so.makeSolver = options.makeSolver;
  so.paced = options.paced;
  so.frameLimit = options.frameLimit;
  so.recordMetrics = options.recordMetrics;
  so.quiet = options.quiet;
  so.wake = [] { glfwPostEmptyEvent(); };
  std::string noContext;
  if (options.solver == "gpu") so.context = v->window_->createShared(&noContext);
  v->session_ = ViewerSession::create(std::move(so), error);
  if (!v->session_) return nullptr;
  ViewerSession& session = *v->session_;
  session.onChange([raw = v.get()] {
    raw->view_->changed();
    raw->updateTitle();
  });
  // Messages from gl (shader logs, GL errors), of either thread, go to the Messages panel.
  gl::setLogSink([&session](gl::LogLevel level, std::string_view text) {
    session.log(level == gl::LogLevel::Error     ? MessageLevel::Error
                : level == gl::LogLevel::Warning ? MessageLevel::Warning
                                                 : MessageLevel::Info,
                std::string(text));
  });
  if (software) session.log(MessageLevel::Warning, gl::softwareRendererWarning(v->renderer()));
  if (!v->view_->hasRenderer())
    session.log(MessageLevel::Error,
                "The renderer did not start; the hair is simulated but not drawn: " +
                    v->view_->status().rendererError);
  if (!noContext.empty())
    session.log(MessageLevel::Warning, "no context for the simulation thread: " + noContext);
  v->requests_ = std::make_unique<Requests>(*v);
  v->panels_ = std::make_unique<PanelState>();
  v->lastFrameStart_ = v->fpsWindowStart_ = Clock::now();
  return v;
}

Viewer::~Viewer() {
  // The simulation first: its thread uses the shared context and the buffers drawn from.
  gl::setLogSink({});
  session_.reset();
  if (window_) window_->makeCurrent();
  // GL objects go before the context.
  view_.reset();
  if (imguiReady_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  window_.reset();
}

const std::string& Viewer::renderer() const {
  return window_->renderer();
}

MetricsLog Viewer::metrics() const {
  MetricsLog m = session_->metrics();
  for (double ms : uiMs_) m.addUiFrame(ms);
  return m;
}

void Viewer::updateTitle() {
  const std::string t = session_->document().title();
  if (t != title_) {
    title_ = t;
    window_->setTitle(t);
  }
}

bool Viewer::reloadShaders() {
  std::string message;
  const bool ok = view_->reloadShaders(&message);
  session_->log(ok ? MessageLevel::Info : MessageLevel::Error, message);
  return ok;
}

PanelView Viewer::panelView() const {
  const ViewerSession& s = *session_;
  return PanelView{.frame = s.simFrame(),
                   .document = s.document(),
                   .stats = stats_,
                   .messages = s.messages(),
                   .presetErrors = s.presetErrors(),
                   .presetErrorsNote = s.presetErrorsNote(),
                   .picture = view_->status(),
                   .import = s.importStatus(),
                   .renderer = window_->renderer(),
                   .loading = s.loading(),
                   .vsync = window_->vsync()};
}

std::string Viewer::defaultScreenshotName() const {
  char stamp[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(stamp, sizeof stamp, "%Y%m%d_%H%M%S", std::localtime(&now));
  return std::string("csmhair_") + stamp + ".png";
}

void Viewer::requestScreenshot(const std::string& path, long minFrame) {
  screenshotPath_ = path;
  screenshotTicket_ = session_->ticket();
  screenshotFrame_ = minFrame;
}

bool Viewer::screenshotDue() const {
  if (screenshotPath_.empty()) return false;
  // Every change made before the request shows, and the frame asked for is there (or will
  // never come: stopped or paused).
  const SimFrame& frame = session_->simFrame();
  if (frame.ticket < screenshotTicket_ || session_->loading()) return false;
  return screenshotFrame_ < 0 || frame.frame >= screenshotFrame_ || frame.idle;
}

void Viewer::handleKeys() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return;  // typing in a text field
  SimControls& controls = session_->controls();
  auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (pressed(GLFW_KEY_SPACE)) controls.setPaused(!controls.paused());
  if (pressed(GLFW_KEY_N) || pressed(GLFW_KEY_PERIOD)) controls.stepOnce();
  if (pressed(GLFW_KEY_R)) controls.resetHair();
  if (pressed(GLFW_KEY_F12) || pressed(GLFW_KEY_P)) requestScreenshot(defaultScreenshotName());
  if (pressed(GLFW_KEY_F)) session_->frameHead();
  if (pressed(GLFW_KEY_HOME)) session_->resetView();
  if (pressed(GLFW_KEY_G)) session_->resetHead();
  if (pressed(GLFW_KEY_F5)) reloadShaders();
  if (pressed(GLFW_KEY_F1)) panels_->showHelp = !panels_->showHelp;
  if (io.KeyCtrl && pressed(GLFW_KEY_S)) session_->save();
}

void Viewer::handleMouse() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureMouse) return;  // over a panel, or a drag that began on one
  const ImVec2 d = io.MouseDelta;
  const bool moved = d.x != 0.0f || d.y != 0.0f;
  const bool left = io.MouseDown[0], right = io.MouseDown[1], middle = io.MouseDown[2];
  ViewerSession& s = *session_;
  if (moved && (right || (left && io.KeyCtrl))) {
    // Turn the head about the neck: the hair reacts on the next step.
    s.dragHead(d.x, d.y);
    view_->moved();
  } else if (moved && (middle || (left && io.KeyShift))) {
    Preset next = s.document().current();
    panCamera(next.view.camera, d.x, d.y, window_->framebufferSize().height);
    s.applyConfig(next);
    view_->moved();
  } else if (moved && left) {
    Preset next = s.document().current();
    orbitCamera(next.view.camera, d.x, d.y);
    s.applyConfig(next);
    view_->moved();
  }
  if (io.MouseWheel != 0.0f) {
    Preset next = s.document().current();
    zoomCamera(next.view.camera, io.MouseWheel);
    s.applyConfig(next);
    view_->moved();
  }
}

// --- Drawing -------------------------------------------------------------------------------

void Viewer::renderScene(bool capture) {
  const SimFrame& frame = session_->simFrame();
  const bool running = !session_->controls().paused() && !frame.idle;
  const SceneView::Drawn drawn = view_->draw(frame, session_->document().current().view,
                                             window_->framebufferSize(), running, capture);
  if (drawn.scene) {
    // The simulation may write this frame's buffer again once these draws are done.
    session_->drawn();
    stats_.renderStages = drawn.stages;
    stats_.drawnStrands = drawn.strands;
  }
}

void Viewer::takeScreenshot() {
  const WindowSize size = window_->framebufferSize();
  lastScreenshot_ = readWindowPixels(size.width, size.height);
  std::string error;
  if (writePng(screenshotPath_, lastScreenshot_, &error)) {
    lastScreenshotPath_ = screenshotPath_;
    session_->log(MessageLevel::Info, "screenshot saved: " + screenshotPath_);
  } else {
    session_->log(MessageLevel::Error, "screenshot failed: " + error);
  }
  screenshotPath_.clear();
}

void Viewer::runFrame() {
  const auto start = Clock::now();
  if (framesDrawn_ > 0) {
    const double ms = std::chrono::duration<double, std::milli>(start - lastFrameStart_).count();
    stats_.frameMs.push(float(ms));
    if (options_.recordMetrics) uiMs_.push_back(ms);
  }
  lastFrameStart_ = start;
  ++fpsWindowFrames_;
  const double window = std::chrono::duration<double>(start - fpsWindowStart_).count();
  if (window >= 1.0) {
    stats_.fps = double(fpsWindowFrames_) / window;
    fpsWindowFrames_ = 0;
    fpsWindowStart_ = start;
  }

  glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();

  session_->update();
  session_->controls().advancePlayback();
  handleKeys();
  handleMouse();
  drawPanels(panelView(), *requests_, *panels_);
  ImGui::Render();
  const bool capture = screenshotDue();
  renderScene(capture);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (capture) takeScreenshot();
  window_->swapBuffers();
  ++framesDrawn_;
}

int Viewer::run() {
  auto seconds = [](double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
  };
  const auto busyBudget = seconds(options_.maxFps > 0.0 ? 1.0 / options_.maxFps : 0.0);
  const auto idleBudget =
      std::max(busyBudget, seconds(options_.idleFps > 0.0 ? 1.0 / options_.idleFps : 0.0));
  ViewerSession& s = *session_;
  while (!window_->shouldClose()) {
    if (options_.frameLimit >= 0 && s.simFrame().idle && !screenshotPending() && !s.loading() &&
        s.simFrame().ticket >= s.ticket())
      break;
    const auto start = Clock::now();
    runFrame();
    // The swap waits for the display where there is one; where it does not (no vsync, a
    // virtual display), keep to maxFps while anything moves and to idleFps when nothing
    // does, and leave the CPU to the simulation. Input and the simulation's new frames
    // (which post an empty event) end the wait early.
    for (;;) {
      const auto now = Clock::now();
      const bool busy = now - window_->lastInput() < std::chrono::seconds(1) || view_->moving() ||
                        screenshotPending() || s.loading() || s.controls().playingRecording() ||
                        s.latestSerial() != s.simFrame().serial;
      const auto next = start + (busy ? busyBudget : idleBudget);
      if (now >= next || window_->shouldClose()) break;
      glfwWaitEventsTimeout(std::chrono::duration<double>(next - now).count());
    }
  }
  return 0;
}

// --- csmhair's window mode ---------------------------------------------------------------

int runViewer(const Options& options, const SceneSetup& scene, const std::string& startupErrors) {
  ViewerOptions vo;
  vo.width = options.width;
  vo.height = options.height;
  vo.solver = options.solver;
  vo.quiet = options.quiet;
  vo.requireGpu = options.requireGpu;
  // A scripted run measures and captures: as fast as the simulation goes, to its last frame.
  const bool scripted = options.exitAfter >= 0;
  vo.vsync = !scripted;
  vo.paced = !scripted;
  vo.frameLimit = options.exitAfter;
  vo.recordMetrics = !options.metrics.empty();
  std::string error;
  std::unique_ptr<Viewer> viewer = Viewer::create(vo, &error);
  if (!viewer) {
    std::fprintf(stderr, "csmhair: %s\n", error.c_str());
    return startupErrors.empty() ? 1 : 2;
  }
  ViewerSession& session = viewer->session();
  if (!session.open(scene.preset, scene.baseDir, startupErrors.empty() ? options.preset : "",
                    &error, scene.head)) {
    std::fprintf(stderr, "csmhair: %s: %s\n", scene.source.c_str(), error.c_str());
    return 2;
  }
  // A shot's cache opened as the file: its frames on the timeline.
  if (!options.fromCache.empty()) {
    CacheManifest m;
    if (!shot_cache::readManifest(options.fromCache, m, &error)) {
      std::fprintf(stderr, "csmhair: %s\n", error.c_str());
      return 2;
    }
    session.openShot(options.fromCache, shot_cache::completeFrames(options.fromCache, m),
                     m.particles);
  }
  // A preset that fails validation opens the window anyway, on the built-in scene, with its
  // messages in front: the artist sees what to fix instead of a closed terminal.
  if (!startupErrors.empty())
    session.showPresetErrors(startupErrors, "not loaded; showing the built-in preset instead");

  const auto start = Clock::now();
  gl::resetReadbackStats();
  // --screenshot: of the frame --exit-after names (the first frame without it).
  if (!options.screenshot.empty())
    viewer->requestScreenshot(options.screenshot, std::max(1L, options.exitAfter));
  viewer->run();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (!scripted) return 0;
  const SimFrame& f = session.simFrame();
  const ViewerStats& s = viewer->stats();
  const MetricsLog m = viewer->metrics();
  if (!options.quiet) {
    std::fprintf(stderr,
                 "csmhair: %ld simulated frames in %.2f s (%.1f ms a frame, the last step "
                 "%.1f ms); %ld UI frames, %.1f ms apart on average; %zu strands, %zu particles, "
                 "solver %s, %s\n",
                 f.frame, seconds, f.frame > 0 ? 1000.0 * seconds / double(f.frame) : 0.0, f.stepMs,
                 viewer->framesDrawn(), s.frameMs.mean(), f.strands, f.particles,
                 solverLabel(f).c_str(), viewer->renderer().c_str());
  }
  if (!options.metrics.empty()) {
    nlohmann::json meta = describeRun(runDescription(scene, f, viewer->renderer()));
    meta["mode"] = "window";
    meta["wall_seconds"] = seconds;
    meta["sim_frames"] = f.frame;
    meta["drawn_strands"] = s.drawnStrands;
    // What both threads read back from the GPU, and the reads that had to wait for it.
    const gl::ReadbackStats read = gl::readbackStats();
    meta["readback"] = {{"reads", read.reads}, {"bytes", read.bytes}, {"waits", read.waits}};
    if (!m.write(options.metrics, meta, &error)) {
      std::fprintf(stderr, "csmhair: %s\n", error.c_str());
      return 1;
    }
  }
  if (!startupErrors.empty()) return 2;
  if (session.controls().nanStopped()) return 1;
  if (!options.screenshot.empty() && viewer->lastScreenshotPath() != options.screenshot) return 1;
  return 0;
}

}  // namespace csm
