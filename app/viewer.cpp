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
#include "app/params.h"
#include "app/preset.h"
#include "app/window.h"
#include "gl/caps.h"
#include "gl/debug.h"
#include "gl/fence.h"
#include "sim/run/make_solver.h"
#include "sim/param/sim_params.h"
#include "sim/run/scene_checks.h"
#include "sim/solver/stiffness.h"

namespace csm {
namespace {

using Clock = std::chrono::steady_clock;

const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

}  // namespace

std::unique_ptr<Viewer> Viewer::create(const ViewerOptions& options, std::string* error) {
  std::unique_ptr<Viewer> v(new Viewer());
  v->options_ = options;
  v->uiThread_ = std::this_thread::get_id();
  if (!v->options_.makeSolver) v->options_.makeSolver = csm::makeSolver;

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

  // Messages from gl (shader logs, GL errors), of either thread, go to the Messages panel.
  gl::setLogSink([raw = v.get()](gl::LogLevel level, std::string_view text) {
    raw->log(level == gl::LogLevel::Error     ? MessageLevel::Error
             : level == gl::LogLevel::Warning ? MessageLevel::Warning
                                              : MessageLevel::Info,
             std::string(text));
  });

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // layout comes from the code, not a stray imgui.ini in the cwd
  ImGui::StyleColorsDark();
  if (std::filesystem::exists(kFontPath)) io.Fonts->AddFontFromFileTTF(kFontPath, 15.0f);
  ImGui_ImplGlfw_InitForOpenGL(v->window_->handle(), true);
  ImGui_ImplOpenGL3_Init("#version 430 core");
  v->imguiReady_ = true;

  if (software) v->log(MessageLevel::Warning, gl::softwareRendererWarning(v->window_->renderer()));

  v->view_ = std::make_unique<SceneView>();
  if (!v->view_->hasRenderer())
    v->log(MessageLevel::Error,
           "The renderer did not start; the hair is simulated but not drawn: " +
               v->view_->rendererError());

  SimThread::Options so;
  so.makeSolver = v->options_.makeSolver;
  so.solver = options.solver;
  so.paced = options.paced;
  so.frameLimit = options.frameLimit;
  so.recordMetrics = options.recordMetrics;
  so.wake = [] { glfwPostEmptyEvent(); };
  // The first scene opens before the window shows: its import says where it stands on stderr.
  so.sayImportProgress = !options.quiet;
  if (options.solver == "gpu") {
    std::string why;
    so.context = v->window_->createShared(&why);
    if (!so.context) v->log(MessageLevel::Warning, "no context for the simulation thread: " + why);
  }
  SimThread::Started started;
  v->sim_ = SimThread::start(std::move(so), &started, error);
  if (!v->sim_) return nullptr;
  if (!started.warning.empty()) v->log(MessageLevel::Warning, started.warning);
  v->controls_ = std::make_unique<SimControls>(
      *v->sim_, v->frame_, v->doc_,
      [raw = v.get()](MessageLevel level, std::string text) { raw->log(level, std::move(text)); });
  v->takeSimFrame();
  v->panels_ = std::make_unique<PanelState>();
  v->lastFrameStart_ = v->fpsWindowStart_ = Clock::now();
  return v;
}

Viewer::~Viewer() {
  // The simulation first: its thread uses the shared context and the buffers drawn from.
  controls_.reset();
  sim_.reset();
  frame_.reset();
  if (window_) window_->makeCurrent();
  // GL objects go before the context.
  view_.reset();
  if (imguiReady_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  gl::setLogSink({});
  window_.reset();
}

void Viewer::log(MessageLevel level, std::string text) {
  if (!options_.quiet && level != MessageLevel::Info)
    std::fprintf(stderr, "csmhair: %s\n", text.c_str());
  ViewerMessage m{level, std::move(text), Clock::now()};
  if (std::this_thread::get_id() != uiThread_) {
    std::lock_guard lock(inboxMutex_);
    inbox_.push_back(std::move(m));
    return;
  }
  messages_.push_back(std::move(m));
  if (messages_.size() > 200) messages_.erase(messages_.begin(), messages_.begin() + 100);
}

void Viewer::drainInbox() {
  std::vector<ViewerMessage> in;
  {
    std::lock_guard lock(inboxMutex_);
    in.swap(inbox_);
  }
  for (ViewerMessage& m : in) messages_.push_back(std::move(m));
  if (messages_.size() > 200) messages_.erase(messages_.begin(), messages_.begin() + 100);
}

MetricsLog Viewer::metrics() const {
  MetricsLog m = sim_->metrics();
  for (double ms : uiMs_) m.addUiFrame(ms);
  return m;
}

// --- The simulation's frames ---------------------------------------------------------------

void Viewer::takeSimFrame() {
  // Events first: the frame taken after them is at least as new as each.
  const std::vector<SimEvent> events = sim_->takeEvents();
  if (std::shared_ptr<const SimFrame> f = sim_->acquire()) frame_ = std::move(f);
  for (const SimEvent& e : events) handle(e);
  drainInbox();
  checkStiffness();
}

void Viewer::handle(const SimEvent& e) {
  switch (e.kind) {
    case SimEvent::Kind::Opened:
      if (pendingOpen_ && pendingOpen_->ticket == e.ticket) {
        doc_.opened(pendingOpen_->preset, pendingOpen_->path);
        pendingOpen_.reset();
        userPose_ = Pose{};
        afterSceneChange();
        log(MessageLevel::Info, "opened " +
                                    (doc_.path().empty() ? "the built-in preset" : doc_.path()) +
                                    ": " + e.text);
        stiffnessWarning_.clear();
      }
      break;
    case SimEvent::Kind::OpenFailed:
      if (pendingOpen_ && pendingOpen_->ticket == e.ticket) {
        const std::string what = pendingOpen_->path.empty() ? "the preset" : pendingOpen_->path;
        openError_ = e.text;
        presetErrors_ = {what + ": " + e.text};
        presetErrorsNote_ = "not loaded; the scene shown is the one that was running";
        log(MessageLevel::Error, what + ": " + e.text);
        pendingOpen_.reset();
      }
      break;
    case SimEvent::Kind::ConfigRefused:
      // The frames carry the config that still runs: the widgets show it again.
      log(MessageLevel::Error, "not applied: " + e.text);
      {
        Preset running = doc_.current();
        running.scene = frame_->config;
        doc_.applied(running);
      }
      updateTitle();
      break;
    case SimEvent::Kind::Regrew:
      log(MessageLevel::Info, "regrew the hair: " + e.text);
      break;
    case SimEvent::Kind::Resumed:
      log(MessageLevel::Info, e.text + "; paused (Space goes on)");
      break;
    case SimEvent::Kind::ResumeFailed:
    case SimEvent::Kind::ExportFailed:
      log(MessageLevel::Error, e.text);
      break;
    case SimEvent::Kind::Exported:
      log(MessageLevel::Info, e.text);
      break;
    case SimEvent::Kind::Nan:
      if (controls_->current(e.ticket)) {
        controls_->setPaused(true);
        log(MessageLevel::Error, e.text + "; paused. R resets the hair to rest.");
      }
      break;
  }
}

bool Viewer::sync(double timeoutSeconds) {
  const bool ok = sim_->sync(timeoutSeconds);
  takeSimFrame();
  return ok;
}

bool Viewer::waitForSimFrame(long frame, double timeoutSeconds) {
  const bool ok =
      sim_->waitFor([frame](const SimFrame& f) { return f.frame >= frame; }, timeoutSeconds);
  takeSimFrame();
  return ok;
}

// --- The scene -------------------------------------------------------------------------

void Viewer::startOpen(const Preset& preset, const std::string& baseDir, const std::string& path,
                       std::shared_ptr<const HeadModel> head) {
  PendingOpen p;
  p.preset = preset;
  p.baseDir = baseDir;
  p.path = path;
  // Running, from the new scene's first frame on (posted first: the open is the last
  // command open() waits for).
  controls_->setPaused(false);
  p.ticket = sim_->open(preset.scene, baseDir, std::move(head));
  pendingOpen_ = std::move(p);
  // A NaN of the old scene goes with it.
  controls_->opened(pendingOpen_->ticket);
}

bool Viewer::open(const Preset& preset, const std::string& baseDir, const std::string& presetPath,
                  std::string* error, std::shared_ptr<const HeadModel> head) {
  openError_.clear();
  startOpen(preset, baseDir, presetPath, std::move(head));
  const long ticket = pendingOpen_->ticket;
  const bool answered = sim_->waitForTicket(ticket);
  takeSimFrame();
  if (!answered) {
    if (error) *error = "the simulation thread did not answer";
    return false;
  }
  if (pendingOpen_ && pendingOpen_->ticket == ticket) {  // no event: cannot happen
    pendingOpen_.reset();
    if (error) *error = "the simulation did not open the preset";
    return false;
  }
  if (!openError_.empty()) {
    if (error) *error = openError_;
    // Said by the caller: not the preset problems window.
    presetErrors_.clear();
    return false;
  }
  return true;
}

bool Viewer::loadPreset(const std::string& path) {
  Preset c = defaultPreset();
  PresetErrors errors;
  if (!csm::loadPreset(path, c, errors)) {
    presetErrors_ = errors.messages;
    presetErrorsNote_ = "not loaded; the scene shown is the one that was running";
    log(MessageLevel::Error, path + " is not a valid preset; the current scene stays");
    return false;
  }
  presetErrors_.clear();
  startOpen(c, std::filesystem::absolute(path).parent_path().string(), path);
  return true;
}

void Viewer::showPresetErrors(const std::string& text, const std::string& note) {
  presetErrors_.clear();
  presetErrorsNote_ = note;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    if (end > start) presetErrors_.push_back(text.substr(start, end - start));
    start = end + 1;
  }
}

bool Viewer::applyConfig(const Preset& next) {
  // Nothing is read from disk here: a changed head.mesh is read by the simulation thread as it
  // regrows, which refuses a bad one (ConfigRefused) and keeps the scene that runs.
  std::vector<std::string> problems = crossCheck(next.scene);
  const std::string capacity = checkCapacity(next.scene);
  if (!capacity.empty()) problems.push_back(capacity);
  if (!problems.empty()) {
    for (const std::string& p : problems) log(MessageLevel::Error, "not applied: " + p);
    doc_.discardEdits();  // the widgets show what runs
    return false;
  }
  const bool sceneChanged = !sameScene(doc_.current().scene, next.scene);
  if (sceneChanged && pendingOpen_) {
    // The edit would land on the preset being replaced; the view may change meanwhile.
    log(MessageLevel::Warning, "not applied: a preset is loading; change it once it shows");
    doc_.discardEdits();
    return false;
  }
  if (sceneChanged) sim_->setConfig(next.scene);
  doc_.applied(next);
  view_->changed();
  updateTitle();
  return true;
}

void Viewer::checkStiffness() {
  if (!frame_->loaded) return;
  if (const std::string groom = groomReportText(frame_->groomReport); groom != groomWarning_) {
    groomWarning_ = groom;
    if (!groom.empty()) log(MessageLevel::Warning, groom);
  }
  const std::string warning = stiffnessWarning(frame_->stiffness);
  if (warning == stiffnessWarning_) return;
  stiffnessWarning_ = warning;
  if (!warning.empty()) log(MessageLevel::Warning, warning);
}

bool Viewer::setParam(std::string_view key, std::string_view text, std::string* error) {
  const PresetParam* p = findParam(key);
  std::string why;
  if (!p) {
    why = std::string(key) + ": unknown parameter";
  } else {
    Preset next = doc_.current();
    why = paramFromText(*p, next, text);
    if (why.empty()) {
      if (applyConfig(next)) return true;
      // applyConfig has said why.
      if (error) *error = messages_.empty() ? "not applied" : messages_.back().text;
      return false;
    } else {
      why = std::string(key) + "=" + std::string(text) + ": " + why;
    }
  }
  log(MessageLevel::Error, why);
  if (error) *error = why;
  return false;
}

bool Viewer::save() {
  if (doc_.path().empty()) {
    log(MessageLevel::Warning, "the built-in preset has no file: use Save as");
    return false;
  }
  return saveAs(doc_.path());
}

bool Viewer::saveAs(const std::string& path) {
  std::string error;
  if (!doc_.saveAs(path, &error)) {
    log(MessageLevel::Error, "save failed: " + error);
    return false;
  }
  log(MessageLevel::Info, "saved " + path);
  updateTitle();
  return true;
}

void Viewer::revert() {
  if (applyConfig(doc_.loaded())) log(MessageLevel::Info, "reverted to the loaded preset");
}

void Viewer::afterSceneChange() {
  view_->changed();
  updateTitle();
}

void Viewer::updateTitle() {
  const std::string t = doc_.title();
  if (t != title_) {
    title_ = t;
    window_->setTitle(t);
  }
}

// --- Running ---------------------------------------------------------------------------

void Viewer::resetView() {
  Preset next = doc_.current();
  next.view.camera = doc_.loaded().view.camera;
  applyConfig(next);
}

void Viewer::frameHead() {
  if (!frame_->head) return;  // nothing loaded yet
  Preset next = doc_.current();
  csm::frameHead(next.view.camera, next.scene, *frame_->head, frame_->headPose);
  applyConfig(next);
}

void Viewer::resetHead() {
  userPose_ = Pose{};
  sim_->setUserPose(userPose_);
}

bool Viewer::reloadShaders() {
  std::string message;
  const bool ok = view_->reloadShaders(&message);
  log(ok ? MessageLevel::Info : MessageLevel::Error, message);
  return ok;
}

void Viewer::setVsync(bool on) {
  window_->setVsync(on);
}

PanelView Viewer::panelView() const {
  return PanelView{.frame = *frame_,
                   .document = doc_,
                   .stats = stats_,
                   .messages = messages_,
                   .presetErrors = presetErrors_,
                   .presetErrorsNote = presetErrorsNote_,
                   .scene = *view_,
                   .import = sim_->importStatus(),
                   .renderer = window_->renderer(),
                   .loading = pendingOpen_.has_value(),
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
  screenshotTicket_ = sim_->ticket();
  screenshotFrame_ = minFrame;
}

bool Viewer::screenshotDue() const {
  if (screenshotPath_.empty()) return false;
  // Every change made before the request shows, and the frame asked for is there (or will
  // never come: stopped or paused).
  if (frame_->ticket < screenshotTicket_ || pendingOpen_) return false;
  return screenshotFrame_ < 0 || frame_->frame >= screenshotFrame_ || frame_->idle;
}

void Viewer::viewChanged() {
  view_->moved();
}

void Viewer::handleKeys() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return;  // typing in a text field
  auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (pressed(GLFW_KEY_SPACE)) controls_->setPaused(!controls_->paused());
  if (pressed(GLFW_KEY_N) || pressed(GLFW_KEY_PERIOD)) controls_->stepOnce();
  if (pressed(GLFW_KEY_R)) controls_->resetHair();
  if (pressed(GLFW_KEY_F12) || pressed(GLFW_KEY_P)) requestScreenshot(defaultScreenshotName());
  if (pressed(GLFW_KEY_F)) frameHead();
  if (pressed(GLFW_KEY_HOME)) resetView();
  if (pressed(GLFW_KEY_G)) resetHead();
  if (pressed(GLFW_KEY_F5)) reloadShaders();
  if (pressed(GLFW_KEY_F1)) panels_->showHelp = !panels_->showHelp;
  if (io.KeyCtrl && pressed(GLFW_KEY_S)) save();
}

void Viewer::handleMouse() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureMouse) return;  // over a panel, or a drag that began on one
  const ImVec2 d = io.MouseDelta;
  const bool moved = d.x != 0.0f || d.y != 0.0f;
  const bool left = io.MouseDown[0], right = io.MouseDown[1], middle = io.MouseDown[2];
  if (moved && (right || (left && io.KeyCtrl))) {
    // Turn the head about the neck: the hair reacts on the next step.
    userPose_ =
        dragHead(userPose_, doc_.current().view.camera, doc_.current().scene.head, d.x, d.y);
    sim_->setUserPose(userPose_);
    viewChanged();
  } else if (moved && (middle || (left && io.KeyShift))) {
    Preset next = doc_.current();
    panCamera(next.view.camera, d.x, d.y, window_->framebufferSize().height);
    applyConfig(next);
    viewChanged();
  } else if (moved && left) {
    Preset next = doc_.current();
    orbitCamera(next.view.camera, d.x, d.y);
    applyConfig(next);
    viewChanged();
  }
  if (io.MouseWheel != 0.0f) {
    Preset next = doc_.current();
    zoomCamera(next.view.camera, io.MouseWheel);
    applyConfig(next);
    viewChanged();
  }
}

// --- Drawing -------------------------------------------------------------------------------

void Viewer::renderScene(bool capture) {
  const bool running = !controls_->paused() && !frame_->idle;
  const SceneView::Drawn drawn =
      view_->draw(*frame_, doc_.current().view, window_->framebufferSize(), running, capture);
  if (drawn.scene) {
    // The simulation may write this frame's buffer again once these draws are done.
    sim_->drawn();
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
    log(MessageLevel::Info, "screenshot saved: " + screenshotPath_);
  } else {
    log(MessageLevel::Error, "screenshot failed: " + error);
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

  takeSimFrame();
  controls_->advancePlayback();
  handleKeys();
  handleMouse();
  drawPanels(panelView(), *this, *panels_);
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
  while (!window_->shouldClose()) {
    if (options_.frameLimit >= 0 && frame_->idle && !screenshotPending() && !pendingOpen_ &&
        frame_->ticket >= sim_->ticket())
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
                        screenshotPending() || pendingOpen_ || controls_->playingRecording() ||
                        sim_->latestSerial() != frame_->serial;
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
  if (!viewer->open(scene.preset, scene.baseDir, startupErrors.empty() ? options.preset : "",
                    &error, scene.head)) {
    std::fprintf(stderr, "csmhair: %s: %s\n", scene.source.c_str(), error.c_str());
    return 2;
  }
  // A preset that fails validation opens the window anyway, on the built-in scene, with its
  // messages in front: the artist sees what to fix instead of a closed terminal.
  if (!startupErrors.empty())
    viewer->showPresetErrors(startupErrors, "not loaded; showing the built-in preset instead");

  const auto start = Clock::now();
  gl::resetReadbackStats();
  // --screenshot: of the frame --exit-after names (the first frame without it).
  if (!options.screenshot.empty())
    viewer->requestScreenshot(options.screenshot, std::max(1L, options.exitAfter));
  viewer->run();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (!scripted) return 0;
  const SimFrame& f = viewer->simFrame();
  const ViewerStats& s = viewer->stats();
  const MetricsLog m = viewer->metrics();
  if (!options.quiet) {
    std::fprintf(stderr,
                 "csmhair: %ld simulated frames in %.2f s (%.1f ms a frame, the last step "
                 "%.1f ms); %ld UI frames, %.1f ms apart on average; %zu strands, %zu particles, "
                 "solver %s, %s\n",
                 f.frame, seconds, f.frame > 0 ? 1000.0 * seconds / double(f.frame) : 0.0, f.stepMs,
                 viewer->framesDrawn(), s.frameMs.mean(), f.strands, f.particles,
                 solverLabel(f).c_str(), viewer->window().renderer().c_str());
  }
  if (!options.metrics.empty()) {
    nlohmann::json meta = describeRun(runDescription(scene, f, viewer->window().renderer()));
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
  if (viewer->controls().nanStopped()) return 1;
  if (!options.screenshot.empty() && viewer->lastScreenshotPath() != options.screenshot) return 1;
  return 0;
}

}  // namespace csm
