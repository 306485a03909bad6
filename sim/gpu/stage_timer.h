// GPU time per stage of the solver's frame: one time-elapsed query around each group of
// dispatches, kept for the last few frames; times() reads the newest frame whose results are
// in, never waiting. Software drivers (llvmpipe) run a dispatch before glDispatchCompute
// returns and report no time for it in their timer queries, so there the stages are timed by
// the CPU clock instead.
#pragma once

#include <array>
#include <chrono>
#include <utility>
#include <vector>

#include "gl/query.h"
#include "sim/core/results.h"

namespace csm::gpu {

enum Stage {
  kIntegrate = 0,
  kShapeMatching,
  kStrainLimiting,
  kGrid,
  kContacts,
  kVolume,
  kStageCount
};

class StageTimer {
 public:
  explicit StageTimer(bool cpuClock) : cpuClock_(cpuClock) {}

  void beginFrame();
  // Ends the open stage, if any, and opens `stage`.
  void stage(Stage stage);
  void endStage();
  // Closes the frame: its times become readable once its queries finish.
  void endFrame();
  std::vector<StageTime> times();
  void clear();

 private:
  struct Frame {
    std::vector<std::pair<int, gl::Query>> queries;
    size_t used = 0;
    bool issued = false;
    std::array<double, kStageCount> cpuMs{};
  };
  bool cpuClock_;
  int open_ = -1;
  std::chrono::steady_clock::time_point start_;
  std::array<Frame, 3> frames_;
  int current_ = 0;
  std::vector<StageTime> last_;
};

}  // namespace csm::gpu
