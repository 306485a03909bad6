#include "app/sim_controls.h"

#include <algorithm>
#include <cmath>

#include "app/params.h"

namespace csm {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

SimControls::SimControls(SimThread& sim, const std::shared_ptr<const SimFrame>& frame,
                         const PresetDocument& doc, Log log)
    : sim_(sim), frame_(frame), doc_(doc), log_(std::move(log)) {}

bool SimControls::nanStopped() const {
  return frame_->nanFrame >= 0 && frame_->ticket >= resetTicket_;
}

void SimControls::setPaused(bool paused) {
  paused_ = paused;
  playing_ = false;
  // Going on from a recorded frame on show is the live frame going on; resumeFrom() goes on
  // from the frame shown.
  if (!paused && frame_->timeline.shown >= 0) sim_.show(-1);
  sim_.setPaused(paused);
}

void SimControls::showRecorded(long frame) {
  if (frame >= 0) paused_ = true;
  sim_.show(frame);
}

void SimControls::playRecording(bool play) {
  const TimelineStatus& t = frame_->timeline;
  playing_ = play && t.first >= 0;
  if (!playing_) return;
  paused_ = true;
  playFrom_ = t.shown >= 0 && t.shown < t.last ? t.shown : t.first;
  playStart_ = Clock::now();
  sim_.show(playFrom_);
}

void SimControls::advancePlayback() {
  if (!playing_) return;
  const TimelineStatus& t = frame_->timeline;
  const double dt = std::max(1e-6, double(frame_->config.sim.dt));
  long frame =
      playFrom_ + long(std::chrono::duration<double>(Clock::now() - playStart_).count() / dt);
  if (t.last < 0) {
    playing_ = false;
    return;
  }
  if (frame > t.last) {
    if (loop_) {
      playFrom_ = t.first;
      playStart_ = Clock::now();
      frame = t.first;
    } else {
      frame = t.last;
      playing_ = false;
    }
  }
  if (frame != t.shown) sim_.show(frame);
}

void SimControls::resumeFrom(long frame) {
  playing_ = false;
  paused_ = true;
  sim_.resume(frame);
}

void SimControls::bake(double seconds) {
  playing_ = false;
  paused_ = false;
  const double dt = std::max(1e-6, double(doc_.current().scene.sim.dt));
  sim_.bake(std::max(1L, std::lround(seconds / dt)));
}

void SimControls::setRecording(bool on) {
  sim_.setRecording(on);
}

void SimControls::setCacheBudget(size_t bytes) {
  sim_.setCacheBudget(bytes);
}

void SimControls::exportRecorded(const std::string& dir, long first, long last) {
  sim_.exportRecorded(dir, first, last);
}

void SimControls::keepAsA() {
  sim_.keepAsA();
}

void SimControls::rerunFromA() {
  const TimelineStatus& t = frame_->timeline;
  if (t.aFirst < 0) return;
  if (t.aGeneration != frame_->generation) {
    log_(MessageLevel::Error,
         "cannot run B: A was recorded on another groom (the hair was regrown since); keep a "
         "new A");
    return;
  }
  playing_ = false;
  paused_ = false;
  sim_.showA(false);
  sim_.resume(t.aFirst);
  sim_.bake(std::max(1L, t.aLast - t.aFirst));
}

void SimControls::showA(bool on) {
  sim_.showA(on);
}

std::vector<std::string_view> SimControls::keysChangedSinceA() const {
  std::vector<std::string_view> keys;
  const std::shared_ptr<const Config>& a = frame_->timeline.aConfig;
  if (!a) return keys;
  Preset then = doc_.current();
  then.scene = *a;
  for (const PresetParam& p : params())
    if (p.group != "Camera" && !sameValue(p, then, doc_.current())) keys.push_back(p.key);
  return keys;
}

void SimControls::stepOnce() {
  setPaused(true);
  sim_.step();
}

void SimControls::resetHair() {
  resetTicket_ = sim_.reset();
  log_(MessageLevel::Info, "hair reset to rest");
}

}  // namespace csm
