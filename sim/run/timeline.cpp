#include "sim/run/timeline.h"

#include <algorithm>

#include "sim/groom/hair_sequence.h"
#include "sim/run/cache_files.h"

namespace csm {

void Timeline::restarted(Simulation& sim) {
  shown_ = -1;
  bakeLeft_ = 0;
  if (recording_) frames_.record(sim);  // frame 0, or the frame a regrow starts from
}

bool Timeline::stepped(Simulation& sim) {
  if (recording_) frames_.record(sim);
  return bakeLeft_ > 0 && --bakeLeft_ == 0;
}

void Timeline::setBudget(size_t bytes) {
  budget_ = bytes;
  const size_t a = a_ ? a_->bytes() : 0;
  frames_.setBudget(budget_ > a ? budget_ - a : 0);
}

void Timeline::openShot(const std::string& dir, long frames, size_t particles) {
  shotDir_ = dir;
  shotFrames_ = std::max(0L, frames);
  shotParticles_ = particles;
  showingShot_ = false;
}

const FrameRecording::Shown* Timeline::frameAt(long frame) {
  if (const FrameRecording::Shown* f = frames_.at(frame)) return f;
  if (frame < 1 || frame > shotFrames_) return nullptr;
  if (shotFrame_.frame == frame && !shotFrame_.positions.empty()) return &shotFrame_;
  std::string error;
  if (!cache::readFrame(shotDir_ + "/frames/" + cache::frameName(frame), frame, shotParticles_,
                        shotFrame_, &error)) {
    shotFrame_ = {};
    return nullptr;
  }
  return &shotFrame_;
}

bool Timeline::show(long frame) {
  frames_.flush();  // the newest frames may still be on their way
  const FrameRecording::Shown* f = frame >= 0 ? frameAt(frame) : nullptr;
  showingShot_ = f && f == &shotFrame_;
  const bool recorded = f || (a_ && a_->at(frame));
  shown_ = frame >= 0 && recorded ? frame : -1;
  return shown_ >= 0;
}

bool Timeline::resume(Simulation& sim, long frame, std::string* message) {
  std::string error;
  double mismatch = 0.0;
  if (!frames_.resume(sim, frame, &error, &mismatch)) {
    if (message) *message = "cannot resume: " + error;
    return false;
  }
  shown_ = -1;
  if (message) {
    *message = "resumed from frame " + std::to_string(frame);
    if (mismatch > 0.0)
      *message += "; stepped again it differs from the recording by up to " +
                  std::to_string(mismatch * 1000.0) + " mm";
  }
  return true;
}

bool Timeline::bake(long frames) {
  bakeLeft_ = bakeTotal_ = std::max(0L, frames);
  shown_ = -1;
  return bakeLeft_ > 0;
}

void Timeline::keepAsA(const Simulation& sim) {
  frames_.flush();
  a_ = std::make_unique<FrameRecording>(frames_);
  aConfig_ = std::make_shared<const Config>(sim.config());
  aGeneration_ = sim.generation();
}

bool Timeline::exportFrames(const Simulation& sim, const std::string& dir, long first, long last,
                            std::string* message) {
  frames_.flush();
  std::string error;
  long written = 0;
  bool ok = io::prepareSequenceDir(dir, &error);
  for (long f = first; ok && f <= last; ++f) {
    const FrameRecording::Shown* shown = frameAt(f);
    if (!shown) {
      error = "frame " + std::to_string(f) + " is not recorded";
      ok = false;
    } else {
      ok = io::writeSequenceFrame(dir, ++written, sim.groom(), shown->positions, &error);
    }
  }
  if (message)
    *message = ok ? "wrote frames " + std::to_string(first) + "-" + std::to_string(last) + " as " +
                        std::to_string(written) + " cyHair files into " + dir
                  : "export: " + error;
  return ok;
}

const FrameRecording::Shown* Timeline::shownFrame(bool* isA) const {
  if (isA) *isA = false;
  if (shown_ < 0) return nullptr;
  if (showingA_ && a_ && a_->at(shown_)) {
    if (isA) *isA = true;
    return a_->at(shown_);
  }
  if (showingShot_ && shotFrame_.frame == shown_) return &shotFrame_;
  return frames_.at(shown_);
}

TimelineStatus Timeline::status(const Simulation& sim) const {
  TimelineStatus t;
  t.recording = recording_;
  t.first = frames_.firstFrame();
  t.last = frames_.lastFrame();
  t.shotFrames = shotFrames_;
  if (shotFrames_ > 0) {  // the slider spans the shot's frames and the recording's
    t.first = t.first < 0 ? 1 : std::min(t.first, 1L);
    t.last = std::max(t.last, shotFrames_);
  }
  t.live = sim.frame();
  t.bytes = frames_.bytes();
  t.budget = budget_;
  t.keyframes = frames_.keyframeCount();
  t.bakeLeft = bakeLeft_;
  t.bakeTotal = bakeTotal_;
  t.refused = frames_.refused();
  t.aFirst = a_ ? a_->firstFrame() : -1;
  t.aLast = a_ ? a_->lastFrame() : -1;
  t.aBytes = a_ ? a_->bytes() : 0;
  t.aConfig = aConfig_;
  t.aGeneration = aGeneration_;
  bool isA = false;
  if (const FrameRecording::Shown* shown = shownFrame(&isA)) {
    t.shown = shown->frame;
    t.showingA = isA;
  }
  return t;
}

}  // namespace csm
