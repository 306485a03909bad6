#include "render/pass_clock.h"

#include <algorithm>

#include "gl/draw.h"

namespace csm {

void PassClock::beginFrame() {
  if (queries_ && !synchronous_) timer_.beginFrame();
}

void PassClock::begin(const char* name) {
  if (*name) begun_.emplace_back(name);
  if (synchronous_) {
    gl::finish();
    const auto now = std::chrono::steady_clock::now();
    if (!open_.empty())
      frame_.push_back(
          {open_, std::chrono::duration<double, std::milli>(now - openStart_).count()});
    open_ = name;
    openStart_ = now;
  } else if (queries_) {
    timer_.begin(name);
  }
}

void PassClock::endFrame() {
  lastBegun_ = std::move(begun_);
  begun_.clear();
  if (synchronous_) {
    begin("");
    open_.clear();
    last_ = std::move(frame_);
    frame_.clear();
  } else if (queries_) {
    timer_.end();
  }
}

std::vector<StageTime> PassClock::times() {
  if (synchronous_) return last_;
  std::vector<StageTime> out;
  if (!queries_) return out;
  timer_.collect();
  for (const gl::StageTimer::Stats& s : timer_.stats())
    if (std::find(lastBegun_.begin(), lastBegun_.end(), s.name) != lastBegun_.end())
      out.push_back({s.name, s.lastMs});
  return out;
}

}  // namespace csm
