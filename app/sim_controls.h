// What the window asks of its simulation thread to run it: pause, step, reset, and the timeline
// (a recorded frame on show, playing the recording back at real time, resume, bake, export, A/B).
// Holds what the window keeps of that (paused, playing back, the reset that clears a NaN stop)
// and posts the commands (app/sim_thread.h); the Viewer's loop advances the playback each frame.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "app/preset_document.h"
#include "app/sim_thread.h"
#include "app/viewer_message.h"

namespace csm {

class SimControls {
 public:
  using Log = std::function<void(MessageLevel, std::string)>;
  // `frame`: the viewer's latest frame (it takes in new ones); `doc`: its preset.
  SimControls(SimThread& sim, const std::shared_ptr<const SimFrame>& frame,
              const PresetDocument& doc, Log log);

  void setPaused(bool paused);
  bool paused() const { return paused_; }
  void stepOnce();   // one frame, paused
  void resetHair();  // back to rest, time 0; clears a NaN stop
  // A new scene opens with the command `ticket`: a NaN of the old one goes with it.
  void opened(long ticket) { resetTicket_ = ticket; }
  // Whether a NaN reported with `ticket` is of the scene as it is (not cleared by a reset since).
  bool current(long ticket) const { return ticket >= resetTicket_; }
  // The simulation stopped on NaN and no reset has cleared it.
  bool nanStopped() const;

  // The timeline (sim/run/timeline.h, run by the simulation thread). Showing a recorded frame
  // pauses the simulation (-1: the live frame again); playing shows the recording at real time
  // from the frame shown, looping or stopping at its end; resume goes on simulating from a
  // recorded frame (paused there); bake runs seconds of simulation as fast as they go.
  void showRecorded(long frame);
  void playRecording(bool play);
  bool playingRecording() const { return playing_; }
  void setLoopRecording(bool loop) { loop_ = loop; }
  bool loopRecording() const { return loop_; }
  void resumeFrom(long frame);
  void bake(double seconds);
  void setRecording(bool on);
  void setCacheBudget(size_t bytes);
  // Writes the recorded frames first..last as DIR/frame_00001.hair, ... (cyHair).
  void exportRecorded(const std::string& dir, long first, long last);
  // A/B: keep the recording as A; simulate its span again from its first frame with the
  // parameters as they are now (B: the same head motion and wind, which follow the clock);
  // show A's frame instead of B's at the frame on show; the parameters B differs in.
  void keepAsA();
  void rerunFromA();
  void showA(bool on);
  std::vector<std::string_view> keysChangedSinceA() const;

  // Each UI frame: the recorded frame that playing back has reached.
  void advancePlayback();

 private:
  SimThread& sim_;
  const std::shared_ptr<const SimFrame>& frame_;
  const PresetDocument& doc_;
  Log log_;
  bool paused_ = false;
  // Playing the recording back: from which frame, since when (the UI's clock).
  bool playing_ = false, loop_ = true;
  long playFrom_ = 0;
  std::chrono::steady_clock::time_point playStart_;
  long resetTicket_ = 0;  // frames before it may still show a NaN the reset clears
};

}  // namespace csm
