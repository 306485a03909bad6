// The viewer's timeline: the frames a simulation ran, kept within a memory budget, to show
// again, step through, export and resume from.
//
// Nothing waits for the GPU: record() asks the solver for a copy of the frame
// (SolverState::copyFrame: on the GPU a copy behind a fence) and the frame joins the recording when
// its copy has arrived, a frame or two later (collect(), called by record(); flush() waits for them
// all). What the accessors see is the frames arrived.
//
// Every recorded frame keeps its positions (xyz a particle: what the renderer and the export
// need); every keyframeEvery-th frame also the whole SimulationState. Resuming from frame k
// restores the last keyframe at or before k and steps on to k, which gives the frames as they
// were recorded (the solvers are deterministic; resume checks it on frame k). Over budget the
// oldest frames go first, a keyframe's span at a time, so the first frame kept is always a
// keyframe and every frame kept can be resumed from. The budget is never exceeded: when the
// newest span alone would, the recording starts again at the new frame.
#pragma once

#include <cstddef>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/run/simulation.h"

namespace csm {

struct FrameRecordingOptions {
  size_t budgetBytes = size_t(512) << 20;
  int keyframeEvery = 30;
};

class FrameRecording {
 public:
  explicit FrameRecording(FrameRecordingOptions options = {});

  const FrameRecordingOptions& options() const { return options_; }
  // A new budget takes effect at once (the oldest spans go when it shrinks).
  void setBudget(size_t bytes);
  void clear();

  // Records the frame `sim` is at (after a step, or frame 0 after a reset). A frame that does
  // not follow the last one recorded (a reset, a regrow, a resume elsewhere) starts again.
  void record(Simulation& sim);
  // Adds the frames whose copies have arrived (without waiting); flush() waits for them all.
  void collect() { collect(false); }
  void flush() { collect(true); }
  // Frames asked for whose copies have not arrived.
  size_t inFlight() const { return pending_.size(); }

  bool empty() const { return frames_.empty(); }
  size_t frameCount() const { return frames_.size(); }
  long firstFrame() const { return frames_.empty() ? -1 : frames_.front().shown.frame; }
  long lastFrame() const { return frames_.empty() ? -1 : frames_.back().shown.frame; }
  size_t keyframeCount() const;
  // Bytes held: positions, saved states and bookkeeping; never above the budget.
  size_t bytes() const { return bytes_; }
  // Frames that could not be kept at all: one keyframe alone is larger than the budget.
  long refused() const { return refused_; }

  // A recorded frame as it is shown: its positions (in the groom's order), its time and where
  // the head was; null when it is not recorded.
  struct Shown {
    long frame = 0;
    double time = 0.0;
    Pose head;
    std::vector<glm::vec3> positions;
  };
  const Shown* at(long frame) const;
  const std::vector<glm::vec3>* positions(long frame) const {
    const Shown* f = at(frame);
    return f ? &f->positions : nullptr;
  }

  // Puts `sim` at recorded frame `frame`: restores the keyframe at or before it and steps on
  // with the parameters those frames ran with; from there the simulation goes on with the
  // parameters it has now (an artist goes back to try a change from there).
  // The recorded frames after it are dropped (the next steps record them again). False, with
  // *error, when the frame is not recorded or its state is not of this scene. *mismatch (when
  // given) gets the largest distance between the frame as recorded and as stepped again (m):
  // 0 for a deterministic solver.
  bool resume(Simulation& sim, long frame, std::string* error, double* mismatch = nullptr);

 private:
  struct Frame {
    Shown shown;
    std::shared_ptr<const SimulationState> key;  // the whole state on keyframes
    size_t bytes() const;
  };
  // A frame asked for, its copy on the way.
  struct Pending {
    Frame frame;
    std::shared_ptr<SimulationState> state;  // keyframes: all but the solver part, filled now
    std::shared_ptr<FrameCopy> copy;
  };
  // Drops the oldest span (a keyframe and the frames up to the next); false when only one is
  // left.
  bool dropOldestSpan();
  void trim();
  void collect(bool wait);
  // Adds an arrived frame within the budget.
  void add(Frame f);

  FrameRecordingOptions options_;
  std::deque<Frame> frames_;
  std::deque<Pending> pending_;
  size_t bytes_ = 0;
  long generation_ = -1;
  long start_ = 0;  // the frame the recording started at: keyframes every keyframeEvery from it
  long lastAsked_ = -1;   // the last frame record() asked for
  bool needKey_ = false;  // the recording starts again: the next frame asked is a keyframe
  long refused_ = 0;
};

}  // namespace csm
