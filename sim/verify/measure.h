// Accuracy measures that need more than one state: time-step error, resolution error,
// pendulum period, energy and stability. Every solver (CPU CSM, GPU CSM, the baselines) is
// measured through the Solver interface, on scenes that any of them can run.
// sim/solver/accuracy.h holds the per-state measures (stretch, head penetration, speed, NaN).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/core/solver.h"

namespace csm {

// A scene to measure on: a groom and the config it runs with (head motion from config.head).
struct Scene {
  Groom groom;
  Config config;
};

// Drives a solver through a scene frame by frame, the head following config.head's motion: the
// solver handed the scene's head and reset at rest, then stepped. On a solver of the caller's,
// or on one it makes and owns (the benchmarks, which hold no solver).
class SceneRunner {
 public:
  SceneRunner(Solver& solver, const Scene& scene);
  // Null when `make` makes none (the GPU solver without a context): ok() says.
  SceneRunner(const SolverMaker& make, const Scene& scene);
  bool ok() const { return solver_ != nullptr; }
  void frame();          // one frame of config.sim.dt
  void runTo(double t);  // frames until time() >= t (within half a frame)
  // One frame timed to its completion (the solver's work waited for before and after), ms.
  double timedFrame();
  double time() const { return double(frames_) * scene_.config.sim.dt; }
  long frames() const { return frames_; }

  // The solver's state and what it says of itself.
  void readPositions(std::vector<glm::vec4>& out) { solver_->state().readPositions(out); }
  void readVelocities(std::vector<glm::vec4>& out) { solver_->state().readVelocities(out); }
  SolverDiagnostics& diagnostics() { return solver_->diagnostics(); }

 private:
  std::unique_ptr<Solver> owned_;
  Solver* solver_ = nullptr;
  const Scene& scene_;
  long frames_ = 0;
};

// ---- Differences between states ------------------------------------------------------------

// RMS and max over particles of the distance between two states, in millimetres.
struct PositionError {
  double rmsMm = 0.0;
  double maxMm = 0.0;
};

// Accumulates squared distances over several comparisons (particles x times); the kinematic
// root particles (the first `pinned` of each strand) are left out: they carry no error.
class ErrorAccumulator {
 public:
  ErrorAccumulator(const Groom& groom, int pinned) : groom_(&groom), pinned_(pinned) {}
  void add(std::span<const glm::vec4> a, std::span<const glm::vec4> b);
  PositionError result() const;

 private:
  const Groom* groom_;
  int pinned_;
  double sum2_ = 0.0, max_ = 0.0;
  uint64_t count_ = 0;
};

// Positions against the same scene run with `ratio` times as many substeps, compared at the
// given times (seconds, on frame boundaries). Meaningful only for scenes without chaotic
// collisions: one strand, or a few hundred swinging strands with hair-hair collision off.
PositionError timeStepError(const SolverMaker& make, const Scene& scene,
                            std::span<const double> times, int ratio = 16);

// ---- Resolution ---------------------------------------------------------------------------

// The strand [a, b) of x sampled at `samples` points evenly spaced in particle parameter
// (rest arc length, as the particles are evenly spaced at rest), linearly between particles.
std::vector<glm::dvec3> sampleStrand(std::span<const glm::vec4> x, uint32_t a, uint32_t b,
                                     int samples);
// RMS distance between two sampled centrelines, in millimetres.
double centrelineRmsMm(std::span<const glm::dvec3> a, std::span<const glm::dvec3> b);

// The stiffness window w counts particles, so the same w spans a shorter piece of a strand
// with more particles. A window given as a length instead: the w whose region [k-w, k+w]
// spans about 2 x windowLength of strand at this segment length (at least 1).
int windowForLength(double windowLength, double segmentLength);

// Kinematic root particles that cover about `clampLength` of strand: 1 + round(clamp / l),
// at least 2 (the root and its direction). Keeps the clamped piece the same length when the
// particle count changes.
int pinnedForLength(double clampLength, double segmentLength);

// One straight strand of `particles` particles and length L, clamped horizontally at the root
// (about L/7 of it kinematic whatever the particle count), released under gravity: it swings
// down and sags. Several strands fan out around the vertical; no head, wind or collisions.
Scene cantileverScene(int particles, double length, int strands = 1);

// The turn (degrees) of a scene's first strand at its last held particle, between the held
// segment before it and the free one after (0 when it has no free particle): how far the clamp
// hinges (METHOD.md section 4.4).
double clampTurnDegrees(const Scene& scene, std::span<const glm::vec4> x);

// ---- Energy and stability -------------------------------------------------------------------

// Kinetic plus gravitational energy of the strands, with each particle's potential measured
// from the lowest point it can reach without stretching (its root's height minus its arc
// length from the root), so the energy of any unstretched state is >= 0. Masses as the solvers
// use them (sim/core/hair_state.h). Without driving forces and without stretch, the energy cannot
// exceed its value at the start: growth beyond it is a numerical instability.
class EnergyMeter {
 public:
  EnergyMeter(const Groom& groom, const SimConfig& sim);
  double operator()(std::span<const glm::vec4> x, std::span<const glm::vec4> v) const;

 private:
  std::vector<uint32_t> first_;
  std::vector<double> mass_, arc_;
  glm::dvec3 up_;
  double g_;
};

enum class Blowup { None = 0, Nan, Stretch, Energy };
const char* blowupName(Blowup b);

struct StabilityResult {
  Blowup blowup = Blowup::None;
  double maxStrain = 0.0;    // largest stretch seen over the run
  double energyRatio = 0.0;  // largest energy over the run / energy at the start
  double time = 0.0;         // when it blew up (or the run's length)
  StiffnessInfo stiffness;   // what the solver ran with
};

// Runs the scene for `duration` seconds and reports the first blow-up: a non-finite position
// or velocity, a segment stretched beyond `maxStretch` (1 = 100%), or the energy growing beyond
// `maxEnergyRatio` times its start (the scene must start at rest with energy > 0 and have no
// driving: no head motion, no wind).
StabilityResult checkStability(Solver& solver, const Scene& scene, double duration,
                               double maxStretch = 1.0, double maxEnergyRatio = 1.25);
// The same on a solver `make` makes (none: an empty result).
StabilityResult checkStability(const SolverMaker& make, const Scene& scene, double duration,
                               double maxStretch = 1.0, double maxEnergyRatio = 1.25);

// ---- Pendulum -------------------------------------------------------------------------------

// Period of a uniform rod of length L swinging about one end: 2 pi sqrt(2L / (3g)) for small
// angles, times the series of the complete elliptic integral for amplitude theta0 (radians).
double rodPendulumPeriod(double length, double gravity, double amplitude = 0.0);

struct PendulumResult {
  double period = 0.0;    // measured, seconds (0 when fewer than two crossings)
  double expected = 0.0;  // rodPendulumPeriod
  double relativeError = 0.0;
  int crossings = 0;
  bool finite = true;
};

// One straight strand of n particles and length L hanging from a fixed root, started at rest
// at `amplitude` radians from the vertical in the x-y plane; collisions, wind and damping off;
// only the root pinned; the CSM window spans the whole strand (a rigid strand; the paper's
// stiffness model, alpha = 1).
Scene pendulumScene(int particles, double length, double amplitude, double frameDt = 1.0 / 60.0);

// Runs the scene `periods` expected periods and measures the period from the zero crossings of
// the angle between the vertical and the line from the root to the strand's centre of mass.
PendulumResult measurePendulum(Solver& solver, const Scene& scene, double periods = 4.0);
PendulumResult measurePendulum(const SolverMaker& make, const Scene& scene, double periods = 4.0);

// ---- Hair-hair ----------------------------------------------------------------------------

// Segment pairs of different strands (or far apart on one) closer than `distance`: with the
// hair radius r, pairs closer than r have crossed into each other.
uint64_t closeSegmentPairs(std::span<const glm::vec4> x, const Groom& groom, double distance);

}  // namespace csm
