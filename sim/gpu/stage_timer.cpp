#include "sim/gpu/stage_timer.h"

#include "gl/draw.h"

namespace csm::gpu {
namespace {
constexpr const char* kStageNames[kStageCount] = {"integrate", "shape_matching", "strain_limiting",
                                                  "grid",      "contacts",       "volume"};
}

void StageTimer::beginFrame() {
  current_ = (current_ + 1) % int(frames_.size());
  Frame& f = frames_[current_];
  f.used = 0;
  f.issued = false;
  f.cpuMs.fill(0.0);
}

void StageTimer::stage(Stage stage) {
  endStage();
  Frame& f = frames_[current_];
  if (cpuClock_) {
    start_ = std::chrono::steady_clock::now();
  } else {
    if (f.used == f.queries.size()) f.queries.emplace_back(stage, gl::Query());
    f.queries[f.used].first = stage;
    f.queries[f.used].second.begin();
    ++f.used;
  }
  open_ = stage;
}

void StageTimer::endStage() {
  if (open_ < 0) return;
  Frame& f = frames_[current_];
  if (cpuClock_) {
    gl::finish();  // a no-op on llvmpipe, whose dispatches have already run
    f.cpuMs[open_] +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
            .count();
  } else {
    f.queries[f.used - 1].second.end();
  }
  open_ = -1;
}

void StageTimer::endFrame() {
  endStage();
  frames_[current_].issued = true;
}

std::vector<StageTime> StageTimer::times() {
  // The newest frame whose queries have all finished; none yet: the last known (no waiting).
  const int n = int(frames_.size());
  int pick = -1;
  for (int k = 0; k < n && pick < 0; ++k) {
    const int i = (current_ - k + n) % n;
    const Frame& f = frames_[i];
    if (f.issued && (f.used == 0 || f.queries[f.used - 1].second.resultAvailable())) pick = i;
  }
  if (pick < 0) return last_;
  std::vector<StageTime> out;
  for (const char* name : kStageNames) out.push_back({name, 0.0});
  const Frame& f = frames_[pick];
  for (int k = 0; k < kStageCount; ++k) out[k].ms += f.cpuMs[k];
  for (size_t i = 0; i < f.used; ++i)
    out[f.queries[i].first].ms += double(f.queries[i].second.result()) * 1e-6;
  last_ = out;
  return out;
}

void StageTimer::clear() {
  for (Frame& f : frames_) f.issued = false;
  last_.clear();
}

}  // namespace csm::gpu
