// The viewer's logic without a window: the preset as a document, the simulation thread and the
// commands the window sends it (SimControls), the scene's latest frame taken in, the messages and
// the preset problems. What a panel edit, a key, a drag or a test script does to the scene happens
// here, through applyConfig, the one setter; the Viewer (app/viewer.h) adds the window, the input,
// the picture and screenshots around it. No window and no GL of its own: with the CPU solver it
// runs anywhere (tests/app/ drive it in the quick tier).
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "app/metrics.h"
#include "app/preset_document.h"
#include "app/preset_value.h"
#include "app/sim_controls.h"
#include "app/sim_thread.h"
#include "app/viewer_message.h"
#include "sim/head/head_model.h"

namespace csm {

struct SessionOptions {
  std::string solver = "gpu";  // falls back to "cpu", with a message, when the GPU one fails
  SolverByName makeSolver;     // solvers by name; tests put their own in. Empty: csm::makeSolver
  // The simulation thread's context, sharing objects with the window's; null for the CPU
  // solver (or no window: then "gpu" falls back to "cpu").
  std::unique_ptr<gl::Context> context;
  bool paced = true;     // keep to real time (off: as fast as it goes)
  long frameLimit = -1;  // the simulation stops after this frame (-1: never)
  bool recordMetrics = false;
  bool quiet = false;          // warnings and errors on stderr too, unless quiet
  std::function<void()> wake;  // from the simulation thread after each frame it publishes
};

class ViewerSession {
 public:
  // Starts the simulation thread and takes in its first (empty) frame. Null with `error` when
  // no solver starts.
  static std::unique_ptr<ViewerSession> create(SessionOptions options, std::string* error);
  ~ViewerSession();
  ViewerSession(const ViewerSession&) = delete;
  ViewerSession& operator=(const ViewerSession&) = delete;

  // Called after anything the picture depends on changed other than the frame (the look, the
  // camera, a new scene): the window draws again and sets its title.
  void onChange(std::function<void()> changed) { changed_ = std::move(changed); }

  // --- The scene -------------------------------------------------------------------------
  // Makes `preset` the current one and waits until it runs; `presetPath` is empty for the
  // built-in one; `head` the scene's head when already built (SceneSetup's), else the scene
  // builds it. False (the running scene stays) when its hair cannot be grown.
  bool open(const Preset& preset, const std::string& baseDir, const std::string& presetPath,
            std::string* error, std::shared_ptr<const HeadModel> head = nullptr);
  // A shot's cache of the scene open (app/shot_cache.h) on the timeline: its frames 1..frames,
  // of `particles` particles, scrubbed and played as recorded frames, the first on show; waits
  // until it is.
  void openShot(const std::string& dir, long frames, size_t particles);
  // Reads and validates a preset file and starts opening it; the running scene stays until
  // the new one is ready. When the file is not a valid preset, or its hair cannot be grown, the
  // current scene stays and the messages go to presetErrors(). False when refused at once.
  bool loadPreset(const std::string& path);
  // The one setter: applies a whole preset (crossCheck and capacity at once, then the
  // simulation's setConfig between its frames, which regrows the hair when a Rebuild
  // parameter changed; a regrow that fails is undone with a message). On failure keeps the
  // running scene and says why.
  bool applyConfig(const Preset& next);
  // One parameter from text, as --set reads it, through applyConfig.
  bool setParam(std::string_view key, std::string_view text, std::string* error = nullptr);
  bool save();  // over the opened preset
  bool saveAs(const std::string& path);
  void revert();     // back to the preset as loaded (or last saved)
  void frameHead();  // the camera on the head where it is
  void resetView();  // the preset's camera
  // The user's turn of the head about the neck (a drag), on top of the preset's motion; undone.
  void dragHead(float dx, float dy);
  void resetHead();
  Preset& editedPreset() { return doc_.edited(); }

  // --- Running ---------------------------------------------------------------------------
  SimControls& controls() { return *controls_; }
  const SimControls& controls() const { return *controls_; }
  // Takes in the simulation's events and latest frame, and messages from other threads; once a
  // UI frame (the window), and by the waits below.
  void update();
  // Waits until the simulation has applied every change made so far, then update(). False on
  // timeout.
  bool sync(double timeoutSeconds = 120.0);
  // Waits until the simulation has reached frame `frame` (or can go no further: paused,
  // stopped on NaN, at the limit), then update().
  bool waitForSimFrame(long frame, double timeoutSeconds = 120.0);
  // After the draws that read the latest frame's positions: the thread may write them again.
  void drawn() { sim_->drawn(); }
  // The last command posted, and the latest frame the thread published (what update() would
  // take in): a screenshot waits for its command's frame, the window for a new one.
  long ticket() const { return sim_->ticket(); }
  long latestSerial() const { return sim_->latestSerial(); }
  bool loading() const { return pendingOpen_.has_value(); }

  // --- State -----------------------------------------------------------------------------
  const SimFrame& simFrame() const { return *frame_; }
  const PresetDocument& document() const { return doc_; }
  SimThread::ImportStatus importStatus() const { return sim_->importStatus(); }
  MetricsLog metrics() const { return sim_->metrics(); }

  // --- Messages --------------------------------------------------------------------------
  // From any thread; a message from another shows from the next update() on.
  void log(MessageLevel level, std::string text);
  const std::vector<ViewerMessage>& messages() const { return messages_; }
  // The preset problems window's lines and title.
  const std::vector<std::string>& presetErrors() const { return presetErrors_; }
  const std::string& presetErrorsNote() const { return presetErrorsNote_; }
  void showPresetErrors(const std::string& text, const std::string& note);
  void dismissPresetErrors() { presetErrors_.clear(); }

 private:
  struct PendingOpen {
    long ticket = 0;
    Preset preset;
    std::string baseDir, path;
  };
  ViewerSession() = default;
  void startOpen(const Preset& preset, const std::string& baseDir, const std::string& path,
                 std::shared_ptr<const HeadModel> head = nullptr);
  void handle(const SimEvent& e);
  void drainInbox();
  void checkStiffness();
  void changed();

  bool quiet_ = false;
  std::function<void()> changed_;
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
  std::string headSummary_;           // what was said of head.mesh's fit
  std::string groomWarning_;          // likewise what the groom's import repaired
  Pose userPose_;
};

}  // namespace csm
