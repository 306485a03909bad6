// The soak (docs/RELIABILITY.md, "Soak"): one scene run for a long time on any solver, the
// head moving and then still, the process's memory read at intervals, the hair compared at the
// end with a run that never moved. csmhair-bench's `soak` section and the tests run it.
#pragma once

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include <glm/vec4.hpp>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/core/solver.h"
#include "sim/verify/measure.h"

namespace csm {

// A long run: `movingFrames` with the head moving, then still for the rest; the memory of the
// process read at intervals; at the end the hair compared with a run of the same scene whose
// head never moved, settled for as long as the soak's still part.
struct SoakOptions {
  long frames = 100000;
  long movingFrames = 20000;    // a whole number of motion periods, so the head stops at rest
  int memorySamples = 100;      // RSS reads over the run
  double warmUpFraction = 0.1;  // memory growth is counted from here
};

// What a soak must keep to (docs/RELIABILITY.md, "Soak"), set from what the soak measures,
// with a margin: the resident set grows under 1 MB after warm-up over 100,000 frames; with
// strand contacts half the strands settle within 3.2-3.5 mm RMS of the rest run, nine in ten
// within 17 (100,000 frames) to 26 mm (10,000), and one or two elsewhere (13 cm).
struct SoakCriteria {
  long memoryGrowthKb = 2048;  // RSS at the end <= RSS after warm-up + this
  // Each strand's RMS distance from its settled rest (its free particles) at the end: with
  // strand contacts a shaken strand may come to lie elsewhere, the others come back.
  double medianStrandMm = 5.0;  // half the strands within this
  double p90StrandMm = 30.0;    // nine in ten within this
};

// Each strand's RMS distance (mm) between two states of its free particles, sorted ascending.
struct StrandDistances {
  std::vector<double> mm;
  double quantile(double q) const;  // 0.5: the median (0 when empty)
  size_t beyond(double mm) const;   // strands farther than mm
};
StrandDistances strandDistances(const Groom& groom, int pinned, const std::vector<glm::vec4>& a,
                                const std::vector<glm::vec4>& b);

struct SoakResult {
  long frames = 0;
  bool finite = true;
  long nonFiniteFrame = -1;
  double maxStrain = 0.0;
  long maxStrainFrame = -1;
  long strainedFrames = 0;  // frames with a segment past the strain limit + 0.005
  double wallSeconds = 0.0;
  double framesPerSecond = 0.0;
  // kB, from /proc/self/status: the resident set at the start, after warm-up, at the end,
  // and its peak (VmHWM) at the end; every sample (frame, kB).
  long rssStartKb = 0, rssWarmKb = 0, rssEndKb = 0, rssMaxKb = 0, hwmEndKb = 0;
  std::vector<std::pair<long, long>> rss;
  // Free particles against the settled rest run (mm) at the end, and the same a moment after
  // the head stopped (how far the motion had taken it).
  PositionError toRest;
  StrandDistances strandsToRest;  // the same per strand
  PositionError atStop;
  // How far the hair moved over the second half of the still part: settled hair does not creep.
  PositionError stillDrift;
  double restWallSeconds = 0.0;
};

// The soak's scene from a preset (the default one): its first `strands` strands, no wind (its
// gusts never let the hair settle), strand contacts (the mode whose lists change size every
// frame; 4x cheaper than the default preset's volume grid), the head shaking 40 deg at 1.5 Hz
// (a whole period every 40 frames of 1/60 s).
Config soakScene(const Config& preset, int strands);

// `base` is run as it is but for head.motion (none in the still part and in the rest run).
SoakResult runSoak(const SolverMaker& make, const Config& base, const SoakOptions& options,
                   const std::function<void(long frame, const SoakResult&)>& progress = {});

// The process's resident set and its peak (kB), from /proc/self/status; 0 where unreadable.
long residentKb();
long peakResidentKb();

}  // namespace csm
