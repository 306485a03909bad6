// Where a long groom import stands, said on stderr: once it has taken a second, each new stage
// and twice a second at most within one (sim/groom/scene_groom.h's ImportProgress). The headless
// run and the window's simulation thread both say it; the window also draws it (panels.cpp).
#pragma once

#include <chrono>
#include <string>
#include <string_view>

namespace csm {

class ImportProgressPrinter {
 public:
  void operator()(std::string_view stage, double done);

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_ = Clock::now(), last_ = start_;
  std::string stage_;
};

}  // namespace csm
