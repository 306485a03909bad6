// The torture map (docs/RELIABILITY.md; the soak is sim/verify/soak.h): a scene pushed to each end
// of every live parameter's range, one factor at a time, on any solver and in every collision mode,
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
#include "sim/core/solver.h"

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

}  // namespace csm
