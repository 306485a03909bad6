// What solvers return: plain structs of measures and settings, read by the frame loop, the
// panels, the metrics and the benchmarks. The code that fills them lives above (sim/solver,
// sim/gpu); the GPU solver's reduction fills the same fields (shaders/sim/measure.comp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "sim/core/config.h"

namespace csm {

// Accuracy measures of one hair state, the same for every solver (sim/solver/accuracy.h).
struct Accuracy {
  double maxStrain = 0.0;          // largest relative stretch |x_i+1 - x_i| / l_i - 1 (0 = rest)
  double meanStrain = 0.0;         // mean of |relative stretch| over segments
  uint64_t headPenetrations = 0;   // free particles inside the head (its field or a sphere)
  uint64_t torsoPenetrations = 0;  // free particles inside the torso, not the head
  double maxSpeed = 0.0;           // m/s
  uint64_t nanCount = 0;           // particles with a non-finite position or velocity
};

// Penetration depth histogram: (contact distance - distance) / r in kDepthBins bins of
// 1/kDepthBinsPerR r each (the last bin holds everything deeper).
inline constexpr int kDepthBinsPerR = 32;
inline constexpr int kDepthBins = 64;

// What a frame's candidate list measured of the state it was built from, where the frame
// starts. With more lists a frame (collision.lists), the crossings, the oversize and the
// crowded segments are summed over its lists; the rest are the first list's.
struct ContactStats {
  uint64_t candidates = 0;    // pairs within 2r + margin
  uint64_t contacts = 0;      // pairs closer than 2r
  uint64_t penetrations = 0;  // pairs closer than r
  uint64_t crossings = 0;     // pairs whose orientation flipped since the previous list
  // Of those, the pairs the groom put closer than 2r (their contact distance is the rest
  // distance: they may cross where they crossed at rest).
  uint64_t crossingsClose = 0;
  // Lists since the solver's reset whose candidates did not fit its buffers (a running
  // count: the substeps of those lists kept the list before; the GPU solver grows the
  // buffers to what the frame's last list needed as the next frame begins; always 0 on the
  // CPU reference, which has no fixed buffers), and segments of this list too long for the
  // grid's cells or with a non-finite end (in no cell: no contacts for them).
  uint64_t overflows = 0;
  uint64_t oversize = 0;
  // Segments of this list left without some or all of their candidates in a crowd: more than
  // CSM_MAX_CANDIDATES (2,048) candidates, or a grid cell so full that the driver cut the
  // search's loops short (GPU only; shaders/sim/bindings.glsl).
  uint64_t crowded = 0;
  // The strands measured: 1 in this many (a mode without strand contacts measures a sample of
  // a large hair's, sim/core/measure_sample.h); the counts are the sample's.
  uint32_t measureStride = 1;
  float maxDepth = 0.0f;  // deepest penetration, in r
  std::array<uint32_t, kDepthBins> depth{};
  // Sums another list's counts and depths into these (the deepest, the running count of
  // overflows, the oversize and the crowded segments are the larger).
  void add(const ContactStats& o);
  // Penetration depth: how far a pair is inside its contact distance (2r, or the rest
  // distance of a pair the groom put closer), in r. The q-quantile (0..1) over the pairs
  // inside it; 0 when none.
  double depthQuantile(double q) const;
};

// The bin of a depth (in r).
inline int depthBin(double depthInR) {
  const int bin = int(depthInR * kDepthBinsPerR);
  return bin < 0 ? 0 : bin >= kDepthBins ? kDepthBins - 1 : bin;
}

// The steps of one frame.
struct FramePlan {
  int substeps = 1;
  double h = 0.0;
  int wanted = 1;       // the steps the stiffness asks for (calibrated)
  bool capped = false;  // wanted > sim.max_substeps: the stiffest strands get alpha = 1, softer
};

// What the panel and the metrics show of the stiffness a solver runs with.
struct StiffnessInfo {
  StiffnessModel model = StiffnessModel::Calibrated;
  FramePlan plan;
  double alphaMin = 0.0, alphaMax = 0.0;
  int windowMin = 0, windowMax = 0;  // particles per side
  double rateMin = 0.0, rateMax = 0.0;
  size_t strands = 0;
  size_t stifferStrands = 0;  // calibrated strands with k h^2 > 1: run at alpha = 1
  // Calibrated: B / (g L^3), L the longest free length of a clamped strand (0 without
  // gravity or such strands): how far the goals oppose gravity (softHairDftl).
  double bendingNumber = 0.0;
  double dftl = 0.0;  // the DFTL correction it runs with
};

// What a solver's scene holds, by kind ("strands", "contacts", ...): the GPU solver's buffers
// (on llvmpipe they are process memory). Empty for a solver that does not count them.
struct MemoryUse {
  std::vector<std::pair<std::string, uint64_t>> bytes;  // kind, bytes
  uint64_t total() const {
    uint64_t sum = 0;
    for (const auto& [kind, b] : bytes) sum += b;
    return sum;
  }
};

struct StageTime {
  std::string name;  // "integrate", "shape_matching", "strain_limiting", "grid", "contacts"
  double ms = 0.0;   // per frame, all substeps
};

// What a solver measures of one frame's state (sim/solver/accuracy.h's measures, with each strand's
// own pinned particles and the head where it was at the end of the frame).
struct FrameSample {
  long frame = -1;
  Accuracy accuracy;
  ContactStats contacts;  // of the candidate list that frame began with
  // Whether `contacts` measured anything: false when the mode builds no candidate lists
  // (hair-hair off) and the solver was not asked to measure contacts anyway.
  bool contactsMeasured = false;
};

}  // namespace csm
