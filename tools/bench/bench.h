// csmhair-bench: speed against accuracy for CSM and the baselines (docs/BENCHMARKS.md,
// section "Speed against accuracy"). The sweeps write CSV; scripts/charts.py draws them.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sim/solver/baselines/baseline_solver.h"
#include "sim/core/config.h"
#include "sim/verify/measure.h"

namespace csm::bench {

struct Options {
  bool quick = false;
  bool gpu = false;               // create a headless GL context and include the GPU solver
  bool charts = true;             // run scripts/charts.py at the end
  int threads = 2;                // workers for the accuracy runs (timings always run alone)
  std::string out;                // CSV and charts; default <source>/docs/charts
  std::string source;             // the repository, for presets/ and scripts/
  std::vector<std::string> only;  // sections to run; empty = all
  bool wants(const std::string& section) const;
};

// One method with one setting: a point on the cost-against-error charts.
struct Setting {
  std::string family;  // "CSM", "CSM, no strain limit", "MS explicit", ... (one colour each)
  std::string label;   // "w2 s4"
  std::string solver = "csm";  // "csm", "csm-direct", "gpu" or a baseline name
  int substeps = 4;            // calibrated: the fewest; the stiffness may ask for more
  // CSM's stiffness model: the paper's (window in particles, alpha = 1) unless a setting says.
  StiffnessModel model = StiffnessModel::Paper;
  int window = 2;                    // paper: particles
  float windowLength = 0.04f;        // calibrated: m
  float bendingStiffness = 3.8e-3f;  // calibrated: m^4/s^2
  int maxSubsteps = 64;              // calibrated
  bool strainLimiting = true;
  float dftl = 0.0f;
  CollisionMode collision = CollisionMode::Head;
  BaselineParams params;

  // Makes the setting's solver: none for "gpu" without a context (SceneRunner::ok).
  SolverMaker maker() const;
  void apply(Config& c) const;  // the scene-independent part of the setting
  bool isCsm() const { return solver.rfind("csm", 0) == 0 || solver == "gpu"; }
};

std::vector<Setting> methodSettings(const Options& o);

// Scenes.
// A few hundred strands of shoulder-length hair on a nodding head, head collisions, no wind:
// smooth enough for time-step error.
Scene mainScene(const Options& o);
// The default preset with a given strand count (the "model no more than a scene needs" study).
Scene presetScene(const Options& o, const std::string& preset, int strands);
// The same scene's config alone, the groom not grown.
Config presetConfig(const Options& o, const std::string& preset, int strands);

// A cantilever strand (cantileverScene) run with a setting: the tip's path, frame by frame,
// and its sag at the end. window < 0 keeps the setting's window; damping < 0 keeps the
// scene's (1/s), a larger one lets the strand settle for the sag.
struct CantileverRun {
  std::vector<glm::dvec3> tip;  // one a frame
  double sagMm = NAN;           // root height minus tip height, mean of the last 0.25 s
  bool finite = true;
};
CantileverRun runCantilever(const Setting& s, int particles, int window, double duration,
                            double damping = -1.0, double gravity = -1.0);
// The cantilever's length: short enough that a CSM strand with w = 2 at 16 particles holds
// part of its shape, so its sag tells stiffnesses apart.
inline constexpr double kCantileverLength = 0.12;
// Sag runs: strong damping settles the strand within about a second, and a weak gravity keeps
// every method away from simply hanging, so the sag tells bending stiffnesses apart.
inline constexpr double kSettleDamping = 10.0;
inline constexpr double kSagGravity = 1.0;

// Wall-clock ms per simulated second of a setting on a scene: `frames` frames after one
// warm-up frame, timed alone, the best of three runs.
double msPerSimulatedSecond(const Setting& s, const Scene& scene, int frames);

// Runs `count` jobs on o.threads workers; job(i) must only touch its own results.
void parallelFor(int count, int threads, const std::function<void(int)>& job);

// Sections; each writes its CSV into o.out and prints progress.
void runMethods(const Options& o);
void runStability(const Options& o);
void runResolution(const Options& o);
void runRegionSums(const Options& o);
void runScaling(const Options& o);
void runSceneChoices(const Options& o);
void runWindow(const Options& o);
// Soft hair without DFTL: energy over B, the steps a frame and the DFTL correction.
void runSoftHair(const Options& o);
void runRecording(const Options& o);
// How far hair moves between searches, in the head's frame, and what a kept list would need
// (tools/bench/motion.cpp).
void runMotion(const Options& o);
// A 5 M point groom's import: time by stage and peak memory (tools/bench/import.cpp).
void runImport(const Options& o);
// The torture map and the soak (tools/bench/torture.cpp, sim/verify/torture.h).
void runTortureMap(const Options& o);
void runSoakSection(const Options& o);

}  // namespace csm::bench
