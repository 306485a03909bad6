// The interactive viewer: a window showing the hair simulating in real time, with Dear ImGui
// panels built from the one parameter table. The main loop follows Dear ImGui's
// example_glfw_opengl3: poll, new frame, widgets, render, swap. Around the viewer's logic
// (app/viewer_session.h: the preset as a document, the simulation thread's commands and events,
// the messages), the picture of the scene (app/scene_view.h) and this, the loop: the window,
// input, the panels, screenshots.
//
// The simulation runs on a thread of its own (SimThread) with a context shared with the
// window's, so the UI, the camera and the panels run at display rate whatever a frame of
// simulation costs; the view shows the latest frame the simulation finished. While the
// camera moves or the hair simulates the scene is drawn in the preset's interactive quality
// (render.interactive_*), in full when still and for screenshots; a scene that has not
// changed is not drawn again (SceneView keeps the last picture in a texture).
//
// Every change of the scene, from a panel widget, the mouse camera, a key or a test script,
// goes through ViewerSession::applyConfig, so what a test drives is what an artist drives.
// Changes reach the simulation between its frames; ViewerSession::sync waits until they have.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "app/cli.h"
#include "app/panels.h"
#include "app/scene_view.h"
#include "app/scene_setup.h"
#include "app/viewer_image.h"
#include "app/viewer_session.h"
#include "app/viewer_stats.h"

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

// The window around a ViewerSession (app/viewer_session.h, the logic: the preset, the simulation
// thread, the messages): the GLFW window and Dear ImGui, the picture (SceneView), input,
// screenshots and the loop. The panels (app/panels.h) see it through what they show (PanelView)
// and what they ask (PanelRequests, which it implements by forwarding to the session and to the
// window); this class's interface is what runViewer needs, tests reaching the rest through
// ViewerProbe (tests/window/viewer_probe.h).
class Viewer {
 public:
  // Opens the window, Dear ImGui, the renderer and the simulation thread. Null when there is
  // no window to open; `error` then says why and points to --headless.
  static std::unique_ptr<Viewer> create(const ViewerOptions& options, std::string* error);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // The scene, the simulation and the messages: what the panels edit and the window shows.
  ViewerSession& session() { return *session_; }
  const ViewerSession& session() const { return *session_; }

  // Saves what the window shows, panels included, at full quality, in the first frame that
  // shows every change made before the request (and, with `minFrame`, simulation frame
  // `minFrame` or later).
  void requestScreenshot(const std::string& path, long minFrame = -1);
  const std::string& lastScreenshotPath() const { return lastScreenshotPath_; }
  // One pass of the main loop: never waits for the simulation.
  void runFrame();
  // Until the window closes; with a frame limit (ViewerOptions::frameLimit), until the
  // simulation has reached it and a pending screenshot is taken. Keeps to maxFps. Returns
  // the exit status.
  int run();

  // The UI's frame times and the strands drawn; UI frames run; the window's GL renderer.
  const ViewerStats& stats() const { return stats_; }
  long framesDrawn() const { return framesDrawn_; }
  const std::string& renderer() const;
  // Every UI frame's interval and the simulation's frames, with ViewerOptions::recordMetrics.
  MetricsLog metrics() const;

 private:
  friend class ViewerProbe;
  class Requests;  // PanelRequests: the session's and the window's
  Viewer();

  // What the panels show this frame.
  PanelView panelView() const;
  std::string defaultScreenshotName() const;
  bool screenshotPending() const { return !screenshotPath_.empty(); }
  bool reloadShaders();
  void handleKeys();
  void handleMouse();
  bool screenshotDue() const;
  void renderScene(bool capture);
  void takeScreenshot();
  void updateTitle();

  ViewerOptions options_;
  std::unique_ptr<GlfwWindow> window_;
  bool imguiReady_ = false;
  std::unique_ptr<SceneView> view_;
  std::unique_ptr<ViewerSession> session_;
  std::unique_ptr<Requests> requests_;
  std::string title_;
  long framesDrawn_ = 0;

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
