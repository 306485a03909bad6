// The viewer's timeline over one Simulation, without threads or GL: the recording of the frames
// it runs (sim/run/frame_recording.h) within one memory budget, a recorded frame on show instead
// of the live one, resuming from a recorded frame, a bake (frames run as fast as they go, then a
// pause), A/B against a kept recording, and the export of recorded frames as cyHair files. The
// window's simulation thread (app/sim_thread.h) drives one between frames; tests drive it alone.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "sim/core/config.h"
#include "sim/run/frame_recording.h"
#include "sim/run/simulation.h"

namespace csm {

// What the timeline holds and shows, as the panels show it.
struct TimelineStatus {
  bool recording = true;
  long first = -1, last = -1;                   // the recorded frames
  long shown = -1;                              // -1: the live frame
  long live = 0;                                // the simulation's own frame
  size_t bytes = 0, budget = 0, keyframes = 0;  // the budget holds `bytes` and `aBytes`
  long bakeLeft = 0, bakeTotal = 0;             // a bake's frames still to run, of how many
  long refused = 0;                             // frames too big for the budget alone
  // A kept recording to compare with (A/B): its frames, its memory, its parameters, and
  // whether the frame on show is A's (the same frame number) instead of the recording's.
  long shotFrames = 0;  // frames 1..shotFrames of a shot's cache to show (openShot)
  long aFirst = -1, aLast = -1;
  long aGeneration = -1;  // the groom A was recorded on (Simulation::generation)
  size_t aBytes = 0;
  bool showingA = false;
  std::shared_ptr<const Config> aConfig;
};

class Timeline {
 public:
  // The hair started again (a scene opened, a regrow, a reset): nothing on show, no bake; the
  // frame it starts from is recorded.
  void restarted(Simulation& sim);
  // After a frame of `sim`: records it. True when that frame ends a bake (the caller pauses).
  bool stepped(Simulation& sim);

  void setRecording(bool on) { recording_ = on; }
  // A shot's cache (app/shot_cache.h) whose frames 1..frames, of `particles` particles, show as
  // recorded frames do (read from DIR/frames/ when shown); the recording's own frames come first.
  // Its frames are shown and exported; they cannot be resumed from (they keep no state).
  void openShot(const std::string& dir, long frames, size_t particles);
  // One budget for the recording and A together: the recording gets what A leaves (A shares the
  // keyframes' saved states with it, but is counted whole).
  void setBudget(size_t bytes);
  // Shows recorded frame `frame` (or the shot's) instead of the live one (-1, or a frame not
  // recorded: live again). True when a recorded frame is on show (the caller pauses).
  bool show(long frame);
  // Puts `sim` at recorded frame `frame` (FrameRecording::resume), nothing on show. True with
  // *message saying so (and how far the frame stepped again differs from the recording), or
  // false with why not.
  bool resume(Simulation& sim, long frame, std::string* message);
  // Runs `frames` frames as fast as they go, recording them; nothing on show. True when there
  // are frames to run (the caller unpauses).
  bool bake(long frames);
  // Keeps the recording as it is now as A, with the parameters and the groom it ran with; the
  // budget is shared anew by the next setBudget.
  void keepAsA(const Simulation& sim);
  // Shows A's frame instead of the recording's at the frame on show (when there is an A).
  void showA(bool on) { showingA_ = on && a_ != nullptr; }
  // Writes recorded frames first..last as DIR/frame_00001.hair, ... (sim/groom/hair_sequence.h).
  // True with *message saying what was written, or false with why not.
  bool exportFrames(const Simulation& sim, const std::string& dir, long first, long last,
                    std::string* message);

  size_t budget() const { return budget_; }
  bool showing() const { return shown_ >= 0; }
  bool baking() const { return bakeLeft_ > 0; }
  // The recorded frame on show (A's where A is shown and has it), or null when live.
  const FrameRecording::Shown* shownFrame(bool* isA = nullptr) const;
  TimelineStatus status(const Simulation& sim) const;

 private:
  FrameRecording frames_;
  bool recording_ = true;
  long shown_ = -1;
  long bakeLeft_ = 0, bakeTotal_ = 0;
  size_t budget_ = FrameRecordingOptions{}.budgetBytes;  // the recording's and A's together
  std::unique_ptr<FrameRecording> a_;                    // the kept recording (A/B)
  std::shared_ptr<const Config> aConfig_;
  long aGeneration_ = -1;
  bool showingA_ = false;
  // The shot's cache: its folder, frames and particles, and the frame of it on show.
  std::string shotDir_;
  long shotFrames_ = 0;
  size_t shotParticles_ = 0;
  FrameRecording::Shown shotFrame_;
  bool showingShot_ = false;
  // Frame `frame` of the recording, else of the shot (read into shotFrame_), else null.
  const FrameRecording::Shown* frameAt(long frame);
};

}  // namespace csm
