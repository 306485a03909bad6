#include "sim/run/frame_recording.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace csm {
namespace {

std::vector<glm::vec3> positionsOf(const Simulation& sim) {
  std::vector<glm::vec4> x;
  sim.readPositions(x);
  return std::vector<glm::vec3>(x.begin(), x.end());
}

}  // namespace

size_t FrameRecording::Frame::bytes() const {
  return sizeof(Frame) + shown.positions.size() * sizeof(glm::vec3) + (key ? key->bytes() : 0);
}

FrameRecording::FrameRecording(FrameRecordingOptions options) : options_(options) {
  options_.keyframeEvery = std::max(1, options_.keyframeEvery);
}

void FrameRecording::setBudget(size_t bytes) {
  options_.budgetBytes = bytes;
  trim();
}

void FrameRecording::clear() {
  frames_.clear();
  pending_.clear();
  bytes_ = 0;
  needKey_ = false;
}

size_t FrameRecording::keyframeCount() const {
  return size_t(std::count_if(frames_.begin(), frames_.end(),
                              [](const Frame& f) { return f.key != nullptr; }));
}

bool FrameRecording::dropOldestSpan() {
  size_t next = 1;
  while (next < frames_.size() && !frames_[next].key) ++next;
  if (next >= frames_.size()) return false;  // one span left (or none)
  for (size_t k = 0; k < next; ++k) {
    bytes_ -= frames_.front().bytes();
    frames_.pop_front();
  }
  return true;
}

void FrameRecording::trim() {
  while (bytes_ > options_.budgetBytes && dropOldestSpan()) {
  }
  if (bytes_ > options_.budgetBytes) clear();  // one span alone is over a shrunk budget
}

void FrameRecording::record(Simulation& sim) {
  const bool any = !frames_.empty() || !pending_.empty();
  if (any && (sim.generation() != generation_ || sim.frame() != lastAsked_ + 1)) clear();
  if (frames_.empty() && pending_.empty()) {
    generation_ = sim.generation();
    start_ = sim.frame();
  }
  if (needKey_) {
    // Starting again after the newest span alone outgrew the budget: from a keyframe.
    start_ = sim.frame();
    needKey_ = false;
  }
  Pending p;
  p.frame.shown.frame = sim.frame();
  p.frame.shown.time = sim.time();
  p.frame.shown.head = sim.headPose();
  if ((p.frame.shown.frame - start_) % options_.keyframeEvery == 0)
    p.state = std::make_shared<SimulationState>();
  p.copy = sim.copyFrame(p.state.get());
  lastAsked_ = sim.frame();
  pending_.push_back(std::move(p));
  collect(false);
}

void FrameRecording::collect(bool wait) {
  while (!pending_.empty() && (wait || pending_.front().copy->ready())) {
    Pending p = std::move(pending_.front());
    pending_.pop_front();
    p.copy->read(p.frame.shown.positions, p.state ? &p.state->solver : nullptr);
    p.frame.key = std::move(p.state);
    add(std::move(p.frame));
  }
}

void FrameRecording::add(Frame f) {
  // The first frame kept is a keyframe: frames after a start again wait for the next one.
  if (frames_.empty() && !f.key) return;
  // Room first, from the oldest spans; when the newest span alone is too big, start again.
  while (bytes_ + f.bytes() > options_.budgetBytes && dropOldestSpan()) {
  }
  if (bytes_ + f.bytes() > options_.budgetBytes) {
    frames_.clear();
    bytes_ = 0;
    if (!f.key) {
      // This frame's state was not kept: the next frame asked for is a keyframe.
      needKey_ = true;
      return;
    }
    if (f.bytes() > options_.budgetBytes) {
      ++refused_;
      return;
    }
  }
  bytes_ += f.bytes();
  frames_.push_back(std::move(f));
}

const FrameRecording::Shown* FrameRecording::at(long frame) const {
  if (frames_.empty() || frame < firstFrame() || frame > lastFrame()) return nullptr;
  return &frames_[size_t(frame - firstFrame())].shown;
}

bool FrameRecording::resume(Simulation& sim, long frame, std::string* error, double* mismatch) {
  flush();
  if (frames_.empty() || frame < firstFrame() || frame > lastFrame()) {
    if (error)
      *error = "frame " + std::to_string(frame) + " is not recorded" +
               (frames_.empty() ? std::string(" (nothing is)")
                                : " (frames " + std::to_string(firstFrame()) + "-" +
                                      std::to_string(lastFrame()) + " are)");
    return false;
  }
  size_t at = size_t(frame - firstFrame());
  size_t key = at;
  while (!frames_[key].key) --key;  // the first frame kept is a keyframe
  // Stepped again with the parameters it ran with; from there on, today's.
  const Config today = sim.config();
  if (!sim.restore(*frames_[key].key, error)) return false;
  for (long f = frames_[key].shown.frame; f < frame; ++f) sim.replayFrame();
  if (!sim.setConfig(today, error)) return false;
  if (mismatch) {
    const std::vector<glm::vec3> now = positionsOf(sim);
    const std::vector<glm::vec3>& then = frames_[at].shown.positions;
    double worst = now.size() == then.size() ? 0.0 : INFINITY;
    for (size_t i = 0; i < now.size() && i < then.size(); ++i)
      worst = std::max(worst, double(glm::length(now[i] - then[i])));
    *mismatch = worst;
  }
  while (frames_.size() > at + 1) {
    bytes_ -= frames_.back().bytes();
    frames_.pop_back();
  }
  lastAsked_ = frame;
  return true;
}

}  // namespace csm
