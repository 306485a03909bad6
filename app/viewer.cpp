#include "app/viewer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app/camera_control.h"
#include "app/panels.h"
#include "app/window.h"
#include "gl/debug.h"
#include "gl/framebuffer.h"
#include "gl/shader_source.h"
#include "render/renderer.h"
#include "sim/gpu/make_solver.h"
#include "sim/metrics.h"
#include "app/params.h"
#include "sim/scene_checks.h"
#include "app/preset.h"

namespace csm {
namespace {

using Clock = std::chrono::steady_clock;

uint64_t countNonFinite(const std::vector<glm::vec4>& x) {
  uint64_t n = 0;
  for (const glm::vec4& p : x)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) ++n;
  return n;
}

const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

}  // namespace

std::unique_ptr<Viewer> Viewer::create(const ViewerOptions& options, std::string* error) {
  std::unique_ptr<Viewer> v(new Viewer());
  v->options_ = options;
  if (!v->options_.makeSolver) v->options_.makeSolver = csm::makeSolver;

  GlfwWindow::Options wo;
  wo.width = options.width;
  wo.height = options.height;
  wo.vsync = options.vsync;
  v->window_ = GlfwWindow::create(wo, error);
  if (!v->window_) return nullptr;

  // Messages from gl (shader logs, GL errors) go to the Messages panel too.
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

  v->renderer_ = Renderer::create(&v->rendererError_);
  if (!v->renderer_) {
    v->log(MessageLevel::Error,
           "The renderer did not start; the hair is simulated but not drawn: " + v->rendererError_);
  }

  std::string solverError;
  std::unique_ptr<Solver> solver = v->options_.makeSolver(options.solver, &solverError);
  if (!solver && options.solver == "gpu") {
    v->log(MessageLevel::Warning,
           "The GPU solver did not start (" + solverError + "); using the CPU solver.");
    solver = v->options_.makeSolver("cpu", &solverError);
  }
  if (!solver) {
    if (error) *error = "no solver: " + solverError;
    return nullptr;
  }
  v->sim_ = std::make_unique<Simulation>(std::move(solver));
  v->panels_ = std::make_unique<PanelState>();
  v->lastFrameStart_ = v->fpsWindowStart_ = Clock::now();
  return v;
}

Viewer::~Viewer() {
  if (window_) window_->makeCurrent();
  // GL objects go before the context.
  sim_.reset();
  renderer_.reset();
  uploaded_ = gl::Buffer(gl::NoCreate);
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
  messages_.push_back({level, std::move(text), Clock::now()});
  if (messages_.size() > 200) messages_.erase(messages_.begin(), messages_.begin() + 100);
}

// --- The scene -------------------------------------------------------------------------

bool Viewer::open(const Preset& preset, const std::string& baseDir, const std::string& presetPath,
                  std::string* error) {
  if (!sim_->load(preset.scene, baseDir, error)) return false;
  sim_->setUserPose(Pose{});
  sim_->reset();
  loaded_ = preset;
  current_ = preset;
  current_.scene = sim_->config();
  edited_ = current_;
  presetPath_ = presetPath;
  paused_ = false;
  afterSceneChange();
  log(MessageLevel::Info, "opened " + (presetPath.empty() ? "the built-in preset" : presetPath) +
                              ": " + std::to_string(sim_->solver().strandCount()) + " strands, " +
                              std::to_string(sim_->solver().particleCount()) + " particles");
  stiffnessWarning_.clear();
  checkStiffness();
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
  std::string error;
  const std::string dir = std::filesystem::absolute(path).parent_path().string();
  if (!open(c, dir, path, &error)) {
    presetErrors_ = {path + ": " + error};
    presetErrorsNote_ = "not loaded; the scene shown is the one that was running";
    log(MessageLevel::Error, path + ": " + error);
    return false;
  }
  presetErrors_.clear();
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
  std::vector<std::string> problems = crossCheck(next.scene);
  const std::string capacity = checkCapacity(next.scene);
  if (!capacity.empty()) problems.push_back(capacity);
  std::string error;
  const long generation = sim_->generation();
  if (problems.empty() && !sim_->setConfig(next.scene, &error)) problems.push_back(error);
  if (!problems.empty()) {
    for (const std::string& p : problems) log(MessageLevel::Error, "not applied: " + p);
    edited_ = current_;  // the widgets show what runs
    return false;
  }
  current_ = next;
  current_.scene = sim_->config();
  edited_ = current_;
  if (sim_->generation() != generation) {
    afterSceneChange();
    log(MessageLevel::Info, "regrew the hair: " + std::to_string(sim_->solver().strandCount()) +
                                " strands, " + std::to_string(sim_->solver().particleCount()) +
                                " particles");
  }
  checkStiffness();
  updateTitle();
  return true;
}

void Viewer::checkStiffness() {
  const std::string warning = stiffnessWarning(sim_->solver().stiffness());
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
    Preset next = current_;
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
  if (presetPath_.empty()) {
    log(MessageLevel::Warning, "the built-in preset has no file: use Save as");
    return false;
  }
  return saveAs(presetPath_);
}

bool Viewer::saveAs(const std::string& path) {
  std::string error;
  if (!csm::savePreset(path, current_, &error)) {
    log(MessageLevel::Error, "save failed: " + error);
    return false;
  }
  loaded_ = current_;
  presetPath_ = path;
  log(MessageLevel::Info, "saved " + path);
  updateTitle();
  return true;
}

void Viewer::revert() {
  if (applyConfig(loaded_)) log(MessageLevel::Info, "reverted to the loaded preset");
}

std::vector<std::string_view> Viewer::modifiedKeys() const {
  std::vector<std::string_view> keys;
  for (const PresetParam& p : params())
    if (p.group != "Camera" && !sameValue(p, loaded_, current_)) keys.push_back(p.key);
  return keys;
}

void Viewer::afterSceneChange() {
  ++sceneVersion_;
  nanFrame_ = -1;
  stats_.maxStrain.clear();
  stats_.accuracy = Accuracy{};
  stats_.sampledFrame = -1;
  updateTitle();
}

void Viewer::updateTitle() {
  std::string t = "csmhair - " + current_.name;
  if (!presetPath_.empty()) t += " (" + presetPath_ + ")";
  if (modified()) t += " *";
  if (t != title_) {
    title_ = t;
    window_->setTitle(t);
  }
}

// --- Running ---------------------------------------------------------------------------

void Viewer::resetHair() {
  sim_->reset();
  afterSceneChange();
  log(MessageLevel::Info, "hair reset to rest");
}

void Viewer::resetView() {
  Preset next = current_;
  next.view.camera = loaded_.view.camera;
  applyConfig(next);
}

void Viewer::frameHead() {
  Preset next = current_;
  csm::frameHead(next.view.camera, next.scene, sim_->headPose());
  applyConfig(next);
}

void Viewer::resetHead() {
  sim_->setUserPose(Pose{});
}

bool Viewer::reloadShaders() {
  if (!renderer_) {
    log(MessageLevel::Error, "no renderer to reload: " + rendererError_);
    return false;
  }
  // From the source tree, unless a folder was chosen (CSM_SHADER_DIR, setShaderDirectory),
  // so edits to shaders/ show at once.
  if (!std::getenv("CSM_SHADER_DIR") && gl::shaderDirectory().empty()) {
#ifdef CSM_SOURCE_DIR
    const std::filesystem::path dir = std::filesystem::path(CSM_SOURCE_DIR) / "shaders";
    if (std::filesystem::is_directory(dir)) gl::setShaderDirectory(dir);
#endif
  }
  std::string buildLog;
  if (renderer_->reloadShaders(&buildLog)) {
    shaderReloadFailed_ = false;
    shaderLog_ = buildLog;
    log(MessageLevel::Info, "shaders reloaded from " + gl::shaderDirectory().string() +
                                (buildLog.empty() ? "" : " (with warnings)"));
    return true;
  }
  shaderReloadFailed_ = true;
  shaderLog_ = buildLog;
  log(MessageLevel::Error, "shader reload failed; the old shaders are still in use");
  return false;
}

bool Viewer::vsync() const {
  return window_->vsync();
}

void Viewer::setVsync(bool on) {
  window_->setVsync(on);
}

std::string Viewer::defaultScreenshotName() const {
  char stamp[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(stamp, sizeof stamp, "%Y%m%d_%H%M%S", std::localtime(&now));
  return std::string("csmhair_") + stamp + ".png";
}

void Viewer::requestScreenshot(const std::string& path) {
  screenshotPath_ = path;
}

void Viewer::handleKeys() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return;  // typing in a text field
  auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (pressed(GLFW_KEY_SPACE)) paused_ = !paused_;
  if (pressed(GLFW_KEY_N) || pressed(GLFW_KEY_PERIOD)) {
    paused_ = true;
    stepRequested_ = true;
  }
  if (pressed(GLFW_KEY_R)) resetHair();
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
    sim_->setUserPose(
        dragHead(sim_->userPose(), current_.view.camera, current_.scene.head, d.x, d.y));
  } else if (moved && (middle || (left && io.KeyShift))) {
    Preset next = current_;
    panCamera(next.view.camera, d.x, d.y, window_->framebufferSize().height);
    applyConfig(next);
  } else if (moved && left) {
    Preset next = current_;
    orbitCamera(next.view.camera, d.x, d.y);
    applyConfig(next);
  }
  if (io.MouseWheel != 0.0f) {
    Preset next = current_;
    zoomCamera(next.view.camera, io.MouseWheel);
    applyConfig(next);
  }
}

void Viewer::simulate() {
  if (nanStopped()) return;
  const auto t0 = Clock::now();
  sim_->stepFrame();
  stats_.simMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  stats_.simStages = sim_->solver().stageTimes();
  stats_.contacts = sim_->solver().contactStats();
}

long Viewer::positionsStamp() const {
  // Changes whenever the positions may have: a step, a reset, a regrow.
  return sim_->frame() * 1000003L + sceneVersion_;
}

void Viewer::stopOnNan(uint64_t count) {
  if (nanStopped()) return;
  nanFrame_ = sim_->frame();
  nanParticles_ = count;
  paused_ = true;
  log(MessageLevel::Error, "the simulation produced NaN at frame " + std::to_string(nanFrame_) +
                               " (" + std::to_string(count) +
                               " particles); paused. R resets the hair to rest.");
}

void Viewer::sample() {
  const long frame = sim_->frame();
  const bool due = stats_.sampledFrame < 0 || frame < stats_.sampledFrame ||
                   frame - stats_.sampledFrame >= stats_.sampleEvery;
  if (!due) return;
  Solver& solver = sim_->solver();
  solver.readPositions(positions_);
  solver.readVelocities(velocities_);
  positionsRead_ = positionsStamp();
  if (restGeneration_ != sim_->generation()) {
    restLengths_ = restLengths(sim_->groom());
    restGeneration_ = sim_->generation();
  }
  const std::vector<Sphere> spheres = worldSpheres(sim_->config().head.spheres, sim_->headPose());
  stats_.accuracy = measureAccuracy(positions_, velocities_, sim_->groom(), restLengths_, spheres,
                                    sim_->config().sim.pinned);
  stats_.sampledFrame = frame;
  stats_.maxStrain.push(float(stats_.accuracy.maxStrain));
  if (stats_.accuracy.nanCount > 0) stopOnNan(stats_.accuracy.nanCount);
}

void Viewer::renderScene() {
  const WindowSize size = window_->framebufferSize();
  const ViewConfig& look = current_.view;
  Solver& solver = sim_->solver();
  unsigned buffer = solver.positionBuffer();
  if (renderer_ && buffer == 0) {
    // A solver that keeps its state on the CPU: upload this frame's positions.
    // The positions are on the CPU anyway, so NaN is caught here on every frame.
    if (positionsRead_ != positionsStamp()) {
      solver.readPositions(positions_);
      positionsRead_ = positionsStamp();
      const uint64_t bad = countNonFinite(positions_);
      if (bad > 0) stopOnNan(bad);
    }
    if (uploaded_.id() == 0) uploaded_ = gl::Buffer();
    uploaded_.upload(positions_);
    buffer = uploaded_.id();
  }
  gl::Framebuffer::bindDefault();
  if (renderer_ && size.width > 0 && size.height > 0) {
    FrameView view;
    view.scene = &sim_->config();
    view.look = &look;
    view.groom = &sim_->groom();
    view.generation = sim_->generation();
    view.head = sim_->headPose();
    view.positionBuffer = buffer;
    view.width = size.width;
    view.height = size.height;
    view.targetFramebuffer = 0;
    renderer_->render(view);
    stats_.renderStages = renderer_->stageTimes();
  } else {
    gl::Framebuffer window = gl::Framebuffer::wrap(0);
    window.clearColor(0, std::array<float, 4>{look.render.background.x, look.render.background.y,
                                              look.render.background.z, 1.0f});
    window.release();
  }
  // The renderer may leave its own framebuffer bound; the UI goes into the window's.
  gl::Framebuffer::bindDefault();
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

void Viewer::updateCounts() {
  const Solver& solver = sim_->solver();
  stats_.particles = solver.particleCount();
  stats_.strands = solver.strandCount();
  stats_.drawnStrands = renderer_ ? drawnStrandCount(stats_.strands, sim_->config()) : 0;
}

void Viewer::runFrame() {
  const auto start = Clock::now();
  if (framesDrawn_ > 0)
    stats_.frameMs.push(
        float(std::chrono::duration<double, std::milli>(start - lastFrameStart_).count()));
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

  handleKeys();
  handleMouse();
  updateCounts();
  drawPanels(*this, *panels_);

  if (!paused_ || stepRequested_) simulate();
  stepRequested_ = false;
  sample();
  ImGui::Render();
  renderScene();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (!screenshotPath_.empty()) takeScreenshot();
  window_->swapBuffers();
  ++framesDrawn_;
}

int Viewer::run(long exitAfter) {
  while (!window_->shouldClose()) {
    if (exitAfter >= 0 && framesDrawn_ >= exitAfter) break;
    runFrame();
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
  // A scripted run measures and captures; it should not wait for the display's refresh.
  vo.vsync = options.exitAfter < 0;
  std::string error;
  std::unique_ptr<Viewer> viewer = Viewer::create(vo, &error);
  if (!viewer) {
    std::fprintf(stderr, "csmhair: %s\n", error.c_str());
    return startupErrors.empty() ? 1 : 2;
  }
  if (!viewer->open(scene.preset, scene.baseDir, startupErrors.empty() ? options.preset : "",
                    &error)) {
    std::fprintf(stderr, "csmhair: %s: %s\n", scene.source.c_str(), error.c_str());
    return 2;
  }
  // A preset that fails validation opens the window anyway, on the built-in scene, with its
  // messages in front: the artist sees what to fix instead of a closed terminal.
  if (!startupErrors.empty())
    viewer->showPresetErrors(startupErrors, "not loaded; showing the built-in preset instead");

  const auto start = Clock::now();
  if (!options.screenshot.empty()) {
    const long at = std::max(1L, options.exitAfter);
    viewer->run(at - 1);
    viewer->requestScreenshot(options.screenshot);
    if (!viewer->window().shouldClose()) viewer->runFrame();
    if (options.exitAfter < 0) viewer->run(-1);
  } else {
    viewer->run(options.exitAfter);
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (options.exitAfter < 0) return 0;
  const ViewerStats& s = viewer->stats();
  if (!options.quiet && viewer->framesDrawn() > 0) {
    // Steady state: the mean interval between frames after the first (which compiles shaders).
    const double ms = s.frameMs.mean();
    std::fprintf(stderr,
                 "csmhair: %ld frames in %.2f s; steady %.2f fps (%.1f ms a frame, of which the "
                 "last simulation step %.1f ms); %zu strands, %zu particles, solver %s, %s\n",
                 viewer->framesDrawn(), seconds, ms > 0.0 ? 1000.0 / ms : 0.0, ms, s.simMs,
                 s.strands, s.particles, std::string(viewer->simulation().solver().name()).c_str(),
                 viewer->window().renderer().c_str());
  }
  if (!startupErrors.empty()) return 2;
  if (viewer->nanStopped()) return 1;
  if (!options.screenshot.empty() && viewer->lastScreenshotPath() != options.screenshot) return 1;
  return 0;
}

}  // namespace csm
