#include "sim/core/results.h"

#include <algorithm>

namespace csm {

double ContactStats::depthQuantile(double q) const {
  uint64_t total = 0;
  for (uint32_t n : depth) total += n;
  if (total == 0) return 0.0;
  // The rank's place inside its bin, linearly; never past the deepest pair measured.
  const double rank = q * double(total);
  double below = 0.0;
  for (int i = 0; i < kDepthBins; ++i) {
    if (below + depth[i] >= rank && depth[i] > 0) {
      const double within = (rank - below) / depth[i];
      return std::min<double>(maxDepth, (i + within) / kDepthBinsPerR);
    }
    below += depth[i];
  }
  return maxDepth;
}

void ContactStats::add(const ContactStats& o) {
  candidates += o.candidates;
  contacts += o.contacts;
  penetrations += o.penetrations;
  crossings += o.crossings;
  crossingsClose += o.crossingsClose;
  overflows = std::max(overflows, o.overflows);  // a running count: the latest
  oversize = std::max(oversize, o.oversize);
  crowded = std::max(crowded, o.crowded);
  measureStride = std::max(measureStride, o.measureStride);
  maxDepth = std::max(maxDepth, o.maxDepth);
  for (int i = 0; i < kDepthBins; ++i) depth[i] += o.depth[i];
}

}  // namespace csm
