// What the Stats panel shows of the window itself: frame times and the render passes. The
// simulation's own figures come with each of its frames (SimFrame).
#pragma once

#include <cstddef>
#include <vector>

#include "app/history.h"
#include "sim/core/results.h"

namespace csm {

struct ViewerStats {
  History frameMs{600};                 // wall time between UI frames: 10 s at 60 fps
  double fps = 0.0;                     // over the last second
  std::vector<StageTime> renderStages;  // of the last scene picture drawn
  std::size_t drawnStrands = 0;         // in the last scene picture
};

}  // namespace csm
