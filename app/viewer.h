// The interactive viewer: a window showing the hair simulating in real time, with Dear ImGui
// panels built from the one parameter table. The main loop follows Dear ImGui's
// example_glfw_opengl3: poll, new frame, widgets, render, swap.
//
// Every change of the scene, from a panel widget, the mouse camera, a key or a test script,
// goes through applyConfig(), so what a test drives is what an artist drives.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "app/cli.h"
#include "app/preset.h"
#include "app/scene_setup.h"
#include "app/viewer_image.h"
#include "app/viewer_stats.h"
#include "gl/buffer.h"
#include "sim/config.h"
#include "sim/gpu/make_solver.h"
#include "sim/simulation.h"

namespace csm {

class GlfwWindow;
class Renderer;
struct PanelState;

using SolverFactory = std::function<std::unique_ptr<Solver>(const std::string&, std::string*)>;

struct ViewerOptions {
  int width = 1280, height = 720;
  std::string solver = "gpu";  // falls back to "cpu", with a message, when the GPU one fails
  bool vsync = true;
  bool quiet = false;
  // Builds solvers by name; tests put their own in. Empty: csm::makeSolver.
  SolverFactory makeSolver;
};

enum class MessageLevel { Info, Warning, Error };
struct ViewerMessage {
  MessageLevel level;
  std::string text;
  std::chrono::steady_clock::time_point when;
};

class Viewer {
 public:
  // Opens the window, Dear ImGui, the renderer and the solver. Null when there is no
  // window to open; `error` then says why and points to --headless.
  static std::unique_ptr<Viewer> create(const ViewerOptions& options, std::string* error);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // --- The scene -------------------------------------------------------------------------
  // Makes `config` the current preset; `presetPath` is empty for the built-in one.
  bool open(const Preset& preset, const std::string& baseDir, const std::string& presetPath,
            std::string* error);
  // Reads and validates a preset file and opens it. When it is not valid the current scene
  // stays and the messages are shown in the window (presetErrors()).
  bool loadPreset(const std::string& path);
  // The one setter: applies a whole config (crossCheck, capacity, then
  // Simulation::setConfig, which regrows the hair when a Rebuild parameter changed). On
  // failure keeps the running scene and shows why.
  bool applyConfig(const Preset& next);
  // One parameter from text, as --set reads it, through applyConfig.
  bool setParam(std::string_view key, std::string_view text, std::string* error = nullptr);
  bool save();  // over the opened preset
  bool saveAs(const std::string& path);
  void revert();  // back to the preset as loaded (or last saved)
  // Parameters that differ from the loaded preset. Camera moves do not count (orbiting
  // should not nag), but Save stores the current view.
  std::vector<std::string_view> modifiedKeys() const;
  bool modified() const { return !modifiedKeys().empty(); }

  // --- Running ---------------------------------------------------------------------------
  void setPaused(bool paused) { paused_ = paused; }
  bool paused() const { return paused_; }
  void stepOnce() { stepRequested_ = true; }
  void resetHair();  // back to rest, time 0; clears a NaN stop
  void resetView();  // the preset's camera
  void frameHead();
  void resetHead();  // undo the mouse's head pose
  bool reloadShaders();
  // Saves what the window shows, panels included, at the end of the next frame.
  void requestScreenshot(const std::string& path);
  // One pass of the main loop.
  void runFrame();
  // Until the window closes, or `exitAfter` frames when >= 0. Returns the exit status.
  int run(long exitAfter);

  // --- State, for the panels and tests ---------------------------------------------------
  Simulation& simulation() { return *sim_; }
  const Simulation& simulation() const { return *sim_; }
  const Preset& preset() const { return current_; }  // what runs and is shown
  Preset& editedConfig() { return edited_; }         // what the widgets edit
  const Preset& loadedConfig() const { return loaded_; }
  const std::string& presetPath() const { return presetPath_; }
  const ViewerStats& stats() const { return stats_; }
  const std::vector<ViewerMessage>& messages() const { return messages_; }
  const std::vector<std::string>& presetErrors() const { return presetErrors_; }
  void dismissPresetErrors() { presetErrors_.clear(); }
  // Shows messages (one a line) in the preset problems window, titled with `note`.
  void showPresetErrors(const std::string& text, const std::string& note);
  const std::string& presetErrorsNote() const { return presetErrorsNote_; }
  const std::string& shaderLog() const { return shaderLog_; }
  bool shaderReloadFailed() const { return shaderReloadFailed_; }
  void dismissShaderLog() {
    shaderLog_.clear();
    shaderReloadFailed_ = false;
  }
  bool hasRenderer() const { return renderer_ != nullptr; }
  const std::string& rendererError() const { return rendererError_; }
  bool nanStopped() const { return nanFrame_ >= 0; }
  long nanFrame() const { return nanFrame_; }
  uint64_t nanParticles() const { return nanParticles_; }
  const Image& lastScreenshot() const { return lastScreenshot_; }
  const std::string& lastScreenshotPath() const { return lastScreenshotPath_; }
  long framesDrawn() const { return framesDrawn_; }
  GlfwWindow& window() { return *window_; }
  bool vsync() const;
  void setVsync(bool on);
  std::string defaultScreenshotName() const;
  void log(MessageLevel level, std::string text);

 private:
  Viewer() = default;
  void handleKeys();
  void handleMouse();
  void simulate();
  void updateCounts();
  void sample();
  long positionsStamp() const;
  void stopOnNan(uint64_t count);
  void renderScene();
  void takeScreenshot();
  void afterSceneChange();
  void updateTitle();
  void checkStiffness();

  ViewerOptions options_;
  std::unique_ptr<GlfwWindow> window_;
  bool imguiReady_ = false;
  std::unique_ptr<Renderer> renderer_;
  std::string rendererError_;
  std::unique_ptr<Simulation> sim_;
  gl::Buffer uploaded_{gl::NoCreate};  // positions of a solver without a GPU buffer
  std::vector<glm::vec4> positions_, velocities_;
  std::vector<double> restLengths_;
  long restGeneration_ = -1;
  long sceneVersion_ = 0;
  long positionsRead_ = -1;  // positionsStamp() of positions_

  Preset current_, edited_, loaded_;
  std::string presetPath_;
  std::vector<std::string> presetErrors_;
  std::string presetErrorsNote_;
  std::string shaderLog_;
  bool shaderReloadFailed_ = false;
  std::vector<ViewerMessage> messages_;
  std::string stiffnessWarning_;  // the last one logged, so a slider does not repeat it

  bool paused_ = false;
  bool stepRequested_ = false;
  long nanFrame_ = -1;
  uint64_t nanParticles_ = 0;
  long framesDrawn_ = 0;
  std::string title_;

  ViewerStats stats_;
  std::chrono::steady_clock::time_point lastFrameStart_{};
  std::chrono::steady_clock::time_point fpsWindowStart_{};
  long fpsWindowFrames_ = 0;

  std::string screenshotPath_;
  Image lastScreenshot_;
  std::string lastScreenshotPath_;

  std::unique_ptr<PanelState> panels_;
};

// csmhair without --headless: opens the window on `scene`. `startupErrors` (a preset that
// failed validation) are shown in the window over the built-in scene. Returns the exit
// status: 1 when no window can be opened.
int runViewer(const Options& options, const SceneSetup& scene, const std::string& startupErrors);

}  // namespace csm
