// The interactive viewer: a window showing the hair simulating in real time, with Dear ImGui
// panels built from the one parameter table. The main loop follows Dear ImGui's
// example_glfw_opengl3: poll, new frame, widgets, render, swap. In three parts: the preset as a
// document (app/preset_document.h), the picture of the scene (app/scene_view.h), and this, the
// loop: the window, input, the simulation thread's commands and events, messages, screenshots.
//
// The simulation runs on a thread of its own (SimThread) with a context shared with the
// window's, so the UI, the camera and the panels run at display rate whatever a frame of
// simulation costs; the view shows the latest frame the simulation finished. While the
// camera moves or the hair simulates the scene is drawn in the preset's interactive quality
// (render.interactive_*), in full when still and for screenshots; a scene that has not
// changed is not drawn again (SceneView keeps the last picture in a texture).
//
// Every change of the scene, from a panel widget, the mouse camera, a key or a test script,
// goes through applyConfig(), so what a test drives is what an artist drives. Changes reach
// the simulation between its frames; sync() waits until they have.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "app/cli.h"
#include "app/panels.h"
#include "app/preset_value.h"
#include "app/preset_document.h"
#include "app/scene_view.h"
#include "app/sim_controls.h"
#include "app/scene_setup.h"
#include "app/sim_thread.h"
#include "app/viewer_image.h"
#include "app/viewer_message.h"
#include "app/viewer_stats.h"
#include "sim/head/head_model.h"

namespace csm {

class GlfwWindow;

struct ViewerOptions {
  int width = 1280, height = 720;
  std::string solver = "gpu";  // falls back to "cpu", with a message, when the GPU one fails
  bool vsync = true;
  bool quiet = false;
  // A software OpenGL renderer (llvmpipe) is an error, not a warning; --require-gpu.
  bool requireGpu = false;
  // The simulation keeps to real time (off: as fast as it goes, for scripted runs and tests).
  bool paced = true;
  // The simulation stops after this frame (-1: never); --exit-after.
  long frameLimit = -1;
  // Keep every UI frame's interval and every simulated frame's figures, for --metrics.
  bool recordMetrics = false;
  // UI frames a second at most, when the swap does not wait for the display (no vsync, or
  // a virtual display): the UI then leaves the CPU to the simulation. At this rate while the
  // user acts, the view moves or the simulation has a new frame to show; otherwise at
  // idleFps, woken at once by input or a new frame.
  double maxFps = 60.0;
  double idleFps = 20.0;
  // Builds solvers by name; tests put their own in. Empty: csm::makeSolver.
  SolverByName makeSolver;
};

// The panels (app/panels.h) see the viewer through what they show (PanelView) and what they ask
// (PanelRequests, implemented here), not through this class's interface, which is main's and
// the tests'.
class Viewer : private PanelRequests {
 public:
  // Opens the window, Dear ImGui, the renderer and the simulation thread. Null when there is
  // no window to open; `error` then says why and points to --headless.
  static std::unique_ptr<Viewer> create(const ViewerOptions& options, std::string* error);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // --- The scene -------------------------------------------------------------------------
  // Makes `preset` the current one and waits until it runs; `presetPath` is empty for the
  // built-in one; `head` the scene's head when already built (SceneSetup's), else the scene
  // builds it. False (the running scene stays) when its hair cannot be grown.
  bool open(const Preset& preset, const std::string& baseDir, const std::string& presetPath,
            std::string* error, std::shared_ptr<const HeadModel> head = nullptr);
  // Reads and validates a preset file and starts opening it; the window keeps drawing the
  // running scene until the new one is ready. When the file is not a valid preset, or its
  // hair cannot be grown, the current scene stays and the messages are shown in the window
  // (presetErrors()). False when the file is refused at once.
  bool loadPreset(const std::string& path) override;
  // One parameter from text, as --set reads it, through applyConfig (the one setter, which the
  // panels' widgets call too).
  bool setParam(std::string_view key, std::string_view text, std::string* error = nullptr);
  bool saveAs(const std::string& path) override;
  void revert() override;  // back to the preset as loaded (or last saved)

  // --- Running ---------------------------------------------------------------------------
  // Pause, step, reset and the timeline: what the window asks of its simulation thread.
  SimControls& controls() override { return *controls_; }
  bool reloadShaders() override;
  // Saves what the window shows, panels included, at full quality, in the first frame that
  // shows every change made before the request (and, with `minFrame`, simulation frame
  // `minFrame` or later).
  void requestScreenshot(const std::string& path, long minFrame = -1);
  bool screenshotPending() const { return !screenshotPath_.empty(); }
  // One pass of the main loop: never waits for the simulation.
  void runFrame();
  // Until the window closes; with a frame limit (ViewerOptions::frameLimit), until the
  // simulation has reached it and a pending screenshot is taken. Keeps to maxFps. Returns
  // the exit status.
  int run();

  // Waits until the simulation has applied every change made so far and takes in its latest
  // frame (for scripts and tests; the window never waits). False on timeout.
  bool sync(double timeoutSeconds = 120.0);
  // Waits until the simulation has reached frame `frame` (or can go no further: paused,
  // stopped on NaN, at the limit), then takes in its latest frame.
  bool waitForSimFrame(long frame, double timeoutSeconds = 120.0);

  // --- State, for main and tests ----------------------------------------------------------
  // The latest frame of the simulation the window has taken in: what is drawn and what the
  // Stats panel shows (time, counts, stiffness, samples, NaN).
  const SimFrame& simFrame() const { return *frame_; }
  // The preset: what runs and is shown, what the widgets edit, as loaded, its file.
  const PresetDocument& document() const { return doc_; }
  // The picture of the scene: the renderer, the quality it was drawn at, the shader log.
  const SceneView& sceneView() const { return *view_; }
  const ViewerStats& stats() const { return stats_; }
  const std::vector<ViewerMessage>& messages() const { return messages_; }
  const std::vector<std::string>& presetErrors() const { return presetErrors_; }
  void dismissPresetErrors() override { presetErrors_.clear(); }
  // Shows messages (one a line) in the preset problems window, titled with `note`.
  void showPresetErrors(const std::string& text, const std::string& note);
  SimThread::ImportStatus importStatus() const { return sim_->importStatus(); }
  const Image& lastScreenshot() const { return lastScreenshot_; }
  const std::string& lastScreenshotPath() const { return lastScreenshotPath_; }
  long framesDrawn() const { return framesDrawn_; }
  GlfwWindow& window() { return *window_; }
  // Every UI frame's interval and the simulation's frames, with ViewerOptions::recordMetrics.
  MetricsLog metrics() const;

 private:
  struct PendingOpen {
    long ticket = 0;
    Preset preset;
    std::string baseDir, path;
  };
  Viewer() = default;

  // PanelRequests: the rest of what the panels ask (the public ones above too).
  Preset& editedPreset() override { return doc_.edited(); }
  // The one setter: applies a whole preset (crossCheck and capacity at once, then the
  // simulation's setConfig between its frames, which regrows the hair when a Rebuild
  // parameter changed; a regrow that fails is undone with a message). On failure keeps the
  // running scene and shows why.
  bool applyConfig(const Preset& next) override;
  bool save() override;  // over the opened preset
  void frameHead() override;
  void resetView() override;  // the preset's camera
  void resetHead() override;  // undo the mouse's head pose
  void screenshot() override { requestScreenshot(defaultScreenshotName()); }
  void dismissShaderLog() override { view_->dismissShaderLog(); }
  void setVsync(bool on) override;
  // What the panels show this frame.
  PanelView panelView() const;

  std::string defaultScreenshotName() const;
  // From any thread; messages from other threads show from the next frame on.
  void log(MessageLevel level, std::string text);
  void startOpen(const Preset& preset, const std::string& baseDir, const std::string& path,
                 std::shared_ptr<const HeadModel> head = nullptr);
  void takeSimFrame();
  void handle(const SimEvent& e);
  void handleKeys();
  void handleMouse();
  void drainInbox();
  bool screenshotDue() const;
  void renderScene(bool capture);
  void takeScreenshot();
  void afterSceneChange();
  void updateTitle();
  void checkStiffness();
  void viewChanged();

  ViewerOptions options_;
  std::unique_ptr<GlfwWindow> window_;
  bool imguiReady_ = false;
  std::unique_ptr<SceneView> view_;
  std::unique_ptr<SimThread> sim_;
  std::shared_ptr<const SimFrame> frame_ = std::make_shared<SimFrame>();

  PresetDocument doc_;
  std::unique_ptr<SimControls> controls_;  // over sim_, frame_ and doc_
  std::optional<PendingOpen> pendingOpen_;
  std::string openError_;  // why the last open failed
  std::vector<std::string> presetErrors_;
  std::string presetErrorsNote_;
  std::vector<ViewerMessage> messages_;
  std::thread::id uiThread_;
  mutable std::mutex inboxMutex_;
  std::vector<ViewerMessage> inbox_;  // from other threads
  std::string stiffnessWarning_;      // the last one logged, so a slider does not repeat it
  std::string groomWarning_;          // likewise what the groom's import repaired

  Pose userPose_;
  long framesDrawn_ = 0;
  std::string title_;

  ViewerStats stats_;
  std::vector<double> uiMs_;  // with recordMetrics
  std::chrono::steady_clock::time_point lastFrameStart_{};
  std::chrono::steady_clock::time_point fpsWindowStart_{};
  long fpsWindowFrames_ = 0;

  std::string screenshotPath_;
  long screenshotTicket_ = 0, screenshotFrame_ = -1;
  Image lastScreenshot_;
  std::string lastScreenshotPath_;

  std::unique_ptr<PanelState> panels_;
};

// csmhair without --headless: opens the window on `scene`. `startupErrors` (a preset that
// failed validation) are shown in the window over the built-in scene. Returns the exit
// status: 1 when no window can be opened.
int runViewer(const Options& options, const SceneSetup& scene, const std::string& startupErrors);

}  // namespace csm
