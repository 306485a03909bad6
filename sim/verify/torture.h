// The torture map and the soak (docs/RELIABILITY.md): a scene pushed to each end of every
// live parameter's range, one factor at a time, on any solver and in every collision mode,
// checked frame by frame for what must never happen: a non-finite state, a segment stretched
// past the strain limit, hair inside the head, hair flung faster than the motion can explain.
// csmhair-bench's `torture` and `soak` sections and the tests run the same cells.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sim/core/config.h"
#include "sim/core/pose.h"
#include "sim/verify/measure.h"

namespace csm {

// One cell: the base scene with one thing changed, in one collision mode.
struct TortureCell {
  std::string axis;   // "base", "dt", "substeps", "window", "wind", "motion", "jump"
  std::string value;  // what the axis is set to, e.g. "1/24", "nod 180 deg 10 Hz", "yaw 90"
  Config config;
  double duration = 2.0;     // simulated seconds
  double jumpTime = -1.0;    // when the head jumps (s; < 0: never)
  Pose jump;                 // the user pose (the viewer's drag) from then on
  std::string name() const;  // "jump=yaw 90 deg, volume+strands"
};

// Which cells: every value of every axis, or only each axis's far ends (the tests).
enum class TortureScope { Full, Corners };

// The one-factor sweeps from `base`, times every collision mode: sim.dt 1/240..1/24 and
// substeps 1..8 (the ranges; each the exact count: the calibrated model's steps are
// capped there), and the parameter table's ends (sim/param/sim_params.cpp) for the rest: the
// calibrated window 0.2 cm..1 m and the paper model's 1..32 particles, wind 0..50 m/s, each
// head motion at the table's largest amplitude (180 deg, 180 cm) and frequency (10 Hz), and
// the head turned 90 deg (yaw or nod about the neck) between two frames. The jump comes at a
// quarter of `duration`.
std::vector<TortureCell> tortureCells(const Config& base, TortureScope scope, double duration);

// What a cell must keep to. The tolerances are fixed here, once, and said in RELIABILITY.md.
struct TortureCriteria {
  double strainTolerance = 0.005;  // max stretch <= sim.strainLimit + this (a tenth of 5%)
  double penetrationMm = 1.0;      // no free particle deeper than this inside the head
  double speedFactor = 3.0;        // peak speed <= factor x reference + free fall (below)
};

struct TortureResult {
  long frames = 0;        // frames run (fewer than asked when the state went non-finite)
  int stepsPerFrame = 0;  // the solver's plan at the end
  bool finite = true;
  long nonFiniteFrame = -1;  // the first frame with a non-finite position or velocity
  double strainLimit = 0.0;  // sim.strainLimit of the cell
  double maxStrain = 0.0;    // largest relative stretch of any segment, any frame
  double deepestMm = 0.0;    // deepest free particle inside the head, any frame (mm)
  uint64_t maxInside = 0;    // most free particles inside the head in one frame
  long insideFrames = 0;     // frames with any free particle inside
  double peakSpeed = 0.0;    // fastest particle, any frame (m/s)
  long peakSpeedFrame = -1;
  // The speed bound: speedFactor x (rigidSpeed + windSpeed) + fallSpeed.
  double rigidSpeed = 0.0;  // fastest any particle of the groom moves when glued to the head
                            // through the head's motion (a jump moves it in no time: none)
  double windSpeed = 0.0;   // fastest the wind blows at any particle, any frame
  double fallSpeed = 0.0;   // sqrt(2 g L) for the longest strand, plus g dt
  double speedBound = 0.0;
  double wallSeconds = 0.0;
  // The verdicts. The head is not a criterion with collisions off (headChecked false).
  bool headChecked = true;
  bool stretchOk = true, headOk = true, speedOk = true;
  bool pass() const { return finite && stretchOk && headOk && speedOk; }
  // The failed criteria with their numbers ("stretch 0.4120 > limit 0.0500; peak speed ...");
  // empty when the cell passes.
  std::string failures() const;
};

// Runs a cell on a new solver from `make` through a Simulation (the head's motion, the jump
// as its user pose) and measures every frame from read-backs of the whole state.
TortureResult runTorture(const SolverMaker& make, const TortureCell& cell,
                         const TortureCriteria& criteria = {});

// ---- The soak -------------------------------------------------------------------------------

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
