// Times the passes of a frame: with GL timer queries on a GPU (no stall; results a few frames
// late), or with glFinish and the CPU clock between passes where queries are not to be
// trusted (software rasterizers; see HairRenderer::setSynchronousTiming), which stalls.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "gl/query.h"
#include "sim/core/results.h"

namespace csm {

class PassClock {
 public:
  explicit PassClock(bool timerQueries) : queries_(timerQueries) {}
  void setSynchronous(bool on) { synchronous_ = on; }
  bool synchronous() const { return synchronous_; }

  void beginFrame();
  // Ends the open pass, if any, and starts `name`.
  void begin(const char* name);
  void endFrame();
  // The latest times of the passes the last frame ran (a pass it skipped, as the follower pass
  // when the guides stand in, is not reported with an old time).
  std::vector<StageTime> times();

 private:
  bool queries_;
  bool synchronous_ = false;
  gl::StageTimer timer_;
  std::string open_;
  std::chrono::steady_clock::time_point openStart_;
  std::vector<StageTime> frame_, last_;
  std::vector<std::string> begun_, lastBegun_;  // the passes of the open and the last frame
};

}  // namespace csm
