// The window's simulation on a thread of its own, with a GL context shared with the window's:
// the UI draws at display rate whatever a frame of simulation costs, and shows the latest
// frame the simulation finished. The thread steps its Simulation's frames as headless runs step
// theirs, so the window samples the same measures under the same NaN policy.
//
// Commands from the UI (open, set the config, reset, pause, ...) are applied between frames
// in the order they were posted. Each returns a ticket, and every published frame carries
// the last ticket applied before it, so the UI and tests know when a change has taken effect
// (sync()).
//
// Positions pass from the simulation's context to the window's through a TripleBuffer
// (app/triple_buffer.h); a CPU solver's are handed over as a host copy instead. The timeline
// (recording, a frame on show, A/B, bake, export) is sim/run/timeline.h's, driven between frames.
#pragma once

#include <array>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <glm/vec4.hpp>

#include "app/metrics.h"
#include "app/sim_frame.h"
#include "app/triple_buffer.h"
#include "gl/context.h"
#include "sim/core/config.h"
#include "sim/core/pose.h"
#include "sim/head/head_model.h"
#include "sim/run/timeline.h"
#include "sim/run/make_solver.h"

namespace csm {

class Simulation;

// What the thread has to say, in order; the UI shows them and keeps its own state in step.
struct SimEvent {
  enum class Kind {
    Opened,         // text: "N strands, M particles"
    OpenFailed,     // text: why
    ConfigRefused,  // text: why; the frames carry the config that still runs
    Regrew,         // text: "N strands, M particles"
    Nan,            // text: the frame and the particle count
    Resumed,        // text: "resumed from frame N"
    ResumeFailed,   // text: why
    Exported,       // text: "wrote N frames ... into DIR"
    ExportFailed,   // text: why
  };
  Kind kind;
  long ticket = 0;
  std::string text;
};

class SimThread {
 public:
  struct Options {
    SolverByName makeSolver;     // by name; the thread makes its solver with its context current
    std::string solver = "gpu";  // falls back to "cpu", with a warning, when it fails
    // The thread's context, sharing objects with the UI's; null for CPU solvers only. The
    // SimThread owns it and destroys it on the thread that destroys the SimThread.
    std::unique_ptr<gl::Context> context;
    // Keep to real time: a frame of dt seconds starts no earlier than dt after the last one
    // (behind real time it runs flat out). Off for scripted runs and tests.
    bool paced = true;
    // Stop stepping after this frame (-1: never). For runs that end at a frame.
    long frameLimit = -1;
    // Record every frame's time and sample for metrics().
    bool recordMetrics = false;
    // Called after each publication, from the simulation thread (glfwPostEmptyEvent).
    std::function<void()> wake;
    // Say a long groom import's progress on stderr too (app/import_progress.h).
    bool sayImportProgress = false;
  };
  struct Started {
    std::string solver;   // the name of the solver it runs
    std::string warning;  // the fallback, when the wanted solver did not start
  };

  // Starts the thread and waits until it has made its solver. Null with `error` when none.
  static std::unique_ptr<SimThread> start(Options options, Started* started, std::string* error);
  // Stops the thread (after the frame it is in) and joins it.
  ~SimThread();
  SimThread(const SimThread&) = delete;
  SimThread& operator=(const SimThread&) = delete;

  // --- Commands: each returns its ticket -------------------------------------------------
  // A new scene, from rest at time 0, the user's head pose cleared. `head`: the scene's head when
  // already built from `config` (SceneSetup's), else it is built with the scene.
  long open(const Config& config, const std::string& baseDir,
            std::shared_ptr<const HeadModel> head = nullptr);
  // Live parameters, or a regrow when a Rebuild parameter changed (the clock runs on).
  long setConfig(const Config& config);
  long reset();  // back to rest, time 0; clears a NaN stop
  long setUserPose(const Pose& pose);
  long setPaused(bool paused);
  long step();  // one frame, while paused
  // The timeline: record every frame (on by default) within a memory budget; show a recorded
  // frame instead of the live one (the simulation pauses; -1: live again); resume the
  // simulation from a recorded frame (paused there); bake: run `frames` frames as fast as
  // they go (recording them), then pause.
  long setRecording(bool on);
  long setCacheBudget(size_t bytes);
  long show(long frame);
  long resume(long frame);
  long bake(long frames);
  // Writes the recorded frames first..last as DIR/frame_00001.hair, ...
  // (sim/groom/hair_sequence.h).
  long exportRecorded(const std::string& dir, long first, long last);
  // A/B: keep the recording as it is now as A (with its parameters); show A's frame instead of
  // the recording's at the frame on show (or not).
  long keepAsA();
  // A shot's cache on the timeline (Timeline::openShot): its frames 1..frames shown as recorded
  // ones, the first on show. Opening another scene, or a regrow, takes it off.
  long openShot(const std::string& dir, long frames, size_t particles);
  long showA(bool on);

  // Waits until every command posted so far is applied and published; false on timeout.
  bool sync(double timeoutSeconds = 120.0);
  // Waits until the command with this ticket (and every one before it) is applied.
  bool waitForTicket(long ticket, double timeoutSeconds = 120.0);
  // Waits until `done` holds for the latest frame, or the thread can step no further
  // (paused, stopped on NaN, at the frame limit); false on timeout.
  bool waitFor(const std::function<bool(const SimFrame&)>& done, double timeoutSeconds = 120.0);

  // --- The UI's side ---------------------------------------------------------------------
  // The latest frame; its positions buffer is the UI's until a later acquire(), and the
  // window's context waits on the GPU for the copy into it. Null before the first frame.
  std::shared_ptr<const SimFrame> acquire();
  // After the draws that read the acquired frame's positions are issued: a fence, so the
  // thread overwrites that buffer only once they are done.
  void drawn();
  // Events since the last call, oldest first.
  std::vector<SimEvent> takeEvents();
  // Every frame's time and sample so far (with Options::recordMetrics).
  MetricsLog metrics() const;
  // Where a groom import on the thread stands (sim/groom/scene_groom.h's ImportProgress); an empty
  // stage when none is running.
  struct ImportStatus {
    std::string stage;
    double done = 0.0;
  };
  ImportStatus importStatus() const;
  long ticket() const;        // the last ticket handed out
  long latestSerial() const;  // of the latest frame published (0 before the first)

 private:
  // The commands posted since the thread last looked, merged (the latest of each kind, the
  // steps summed) and applied together in a fixed order (apply). A new command is a field here,
  // its method and its line in apply or applyTimeline.
  struct TimelineEdits {
    std::optional<bool> recording;
    std::optional<size_t> budget;
    std::optional<long> show, resume, bake;
    std::optional<std::pair<std::string, std::pair<long, long>>> exportRange;
    bool keepA = false;
    std::optional<bool> showA;
    struct Shot {
      std::string dir;
      long frames = 0;
      size_t particles = 0;
    };
    std::optional<Shot> shot;
  };
  struct OpenScene {
    Config config;
    std::string baseDir;
    std::shared_ptr<const HeadModel> head;  // null: built with the scene
  };
  struct Pending {
    bool posted = false;  // a command came
    std::optional<OpenScene> open;
    std::optional<Config> config;
    long openTicket = 0, configTicket = 0;  // the commands' own tickets, for their events
    bool reset = false;
    std::optional<Pose> userPose;
    std::optional<bool> paused;
    int steps = 0;
    TimelineEdits timeline;
    bool quit = false;
    bool any() const { return posted; }
  };

  explicit SimThread(Options options);
  void run(std::string* startError, Started* started);
  bool makeSimulation(std::string* error, Started* started);
  long post(const std::function<void(Pending&, long ticket)>& edit);
  void apply(Pending& p, long ticket);
  bool applyTimeline(const Pending& p, long ticket);  // true when it resumed
  bool canStep() const;
  void stepFrame();
  void publish(long ticket);
  void event(SimEvent::Kind kind, long ticket, std::string text);
  std::string counts() const;

  Options options_;
  std::thread thread_;

  // Shared with the UI, under mutex_.
  mutable std::mutex mutex_;
  std::condition_variable wakeThread_, published_;
  Pending pending_;
  long posted_ = 0;
  std::shared_ptr<const SimFrame> latest_;
  std::vector<SimEvent> events_;
  TripleBuffer buffers_;  // the positions handed to the window
  MetricsLog metricsLog_;
  bool running_ = true;  // false once the thread has left its loop
  mutable std::mutex importMutex_;
  ImportStatus import_;

  // The thread's own.
  bool gl_ = false;  // its context is current
  std::unique_ptr<Simulation> sim_;
  bool loaded_ = false;
  bool paused_ = false;
  int steps_ = 0;
  long applied_ = 0;
  long serial_ = 0;
  History maxStrain_{120};
  Timeline timeline_;
  // Real-time pacing: the wall time and sim time the clock last started from.
  std::chrono::steady_clock::time_point anchorWall_;
  double anchorSim_ = 0.0;
};

}  // namespace csm
