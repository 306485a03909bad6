// The solvers behind three narrow interfaces: every solver (the CPU reference, sim/solver; the GPU
// solver, sim/gpu; the baselines the benchmarks compare with) is a Solver, the core that steps the
// hair; it offers its hair's state (SolverState: read, written, saved, copied, carried) and what
// it can say of itself (SolverDiagnostics: samples, stage times, stiffness, memory, failure),
// each asked for by the callers that need it. Simulation (sim/run/simulation.h) holds the one
// solver of a scene and hands out what the app draws and shows; nothing above sim/ holds a Solver.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/core/pose.h"
#include "sim/core/results.h"

namespace csm {

class HeadModel;  // sim/head/head_model.h
class SolverState;
class SolverDiagnostics;

// Everything a solver's next frames depend on, as bytes in the solver's own precision
// (positions, velocities, each region's rotation, its clock and head): restored, the solver
// runs on exactly as it did from there (the viewer's timeline, sim/run/frame_recording.h).
struct SavedState {
  std::vector<std::byte> bytes;
};

// A copy of the frame a solver is at, made where its state lives and read once it has arrived
// (SolverState::copyFrame): the GPU solver copies into a staging buffer behind a fence, so
// nothing waits for the GPU until read(), and read() only when the GPU has not got there yet.
class FrameCopy {
 public:
  virtual ~FrameCopy() = default;
  // Whether read() would return without waiting.
  virtual bool ready() const = 0;
  // The positions (xyz a particle) and, when the copy was asked with the state, the solver's
  // state as SolverState::save would have written it then (into `state` when given).
  virtual void read(std::vector<glm::vec3>& positions, SavedState* state) = 0;
};

// The hair a solver holds: strands and particles.
struct SolverCounts {
  size_t strands = 0;
  size_t particles = 0;
};

// The core: what every caller of a solver needs to run a scene on it.
class Solver {
 public:
  virtual ~Solver() = default;
  virtual std::string_view name() const = 0;

  // The head the next resets collide with, built once by whoever loaded the scene (Simulation:
  // sim/head/head_model.h). A solver never handed one steps nothing and says so
  // (SolverDiagnostics::failure).
  virtual void setHead(std::shared_ptr<const HeadModel> head) = 0;
  // Rebuilds everything from a groom: positions at rest under `head`, zero velocities.
  virtual void reset(const Groom& groom, const Config& config, const Pose& head) = 0;
  // Live parameters; takes effect on the next step.
  virtual void setConfig(const Config& config) = 0;
  // One frame of config.sim.dt seconds, the head moving from `from` to `to`: sim.substeps steps,
  // or with the calibrated stiffness model as many as planFrame (sim/solver/stiffness.h) asks.
  // The head follows `path` through the frame: each step's pose is the path's at its end.
  virtual void stepFrame(const FramePath& path) = 0;
  // A frame whose head moves from `from` to `to`, slerped between.
  void stepFrame(const Pose& from, const Pose& to) { stepFrame(FramePath{{from, to}, {}}); }

  virtual SolverCounts counts() const = 0;
  virtual double time() const = 0;

  // The hair's state and what the solver says of itself: interfaces of the same object.
  virtual SolverState& state() = 0;
  virtual SolverDiagnostics& diagnostics() = 0;

  size_t strandCount() const { return counts().strands; }
  size_t particleCount() const { return counts().particles; }
};

// The hair's state: read back (tests, exports, the CPU solvers' drawing), written (tests, a
// resumed state), saved and restored (the timeline), copied for a later read (the recording),
// carried with a head that jumps.
class SolverState {
 public:
  // Positions (w 1) and velocities (w 0), a vec4 a particle in particle order: read-backs of
  // the whole state (each a GPU stall on the GPU solver); the frame loop samples instead
  // (SolverDiagnostics::requestSample).
  virtual void readPositions(std::vector<glm::vec4>& out) = 0;
  virtual void readVelocities(std::vector<glm::vec4>& out) = 0;
  // Replaces positions and velocities (the layout readPositions gives); the rest of the
  // solver's state (region rotations, contact forces) stays. For tests, and to resume a state.
  virtual void write(const std::vector<glm::vec4>& positions,
                     const std::vector<glm::vec4>& velocities) = 0;
  // Saves, and restores, what the next frames depend on, so that a restored solver steps to the
  // same bits. restore fails (false, *error set) for a state of another scene (another particle
  // count) or of another solver.
  virtual void save(SavedState& out) = 0;
  virtual bool restore(const SavedState& in, std::string* error) = 0;
  // The frame as it stands, for a reader that can take it a few frames later (the viewer's
  // recording): the positions, and with `withState` what save saves.
  virtual std::unique_ptr<FrameCopy> copyFrame(bool withState) = 0;
  // Moves the whole hair rigidly by `by` (positions, velocities and whatever rotations the
  // solver keeps), and the head where the last frame left it, as if the hair were fixed to the
  // head: what a head that jumps does to it (Simulation::stepFrame).
  virtual void carry(const Pose& by) = 0;
  // The GL name of an SSBO holding the current positions (vec4 per particle, in particle
  // order) when the solver keeps them on the GPU; 0 when the caller must upload readPositions.
  virtual unsigned positionBuffer() { return 0; }

 protected:
  ~SolverState() = default;
};

// What a solver says of itself: the measures of its frames (sampled without waiting), where a
// frame's time went, what it runs with and holds, and why it cannot run.
class SolverDiagnostics {
 public:
  // How it runs, where it has a choice (the GPU solver: its kernel path); empty otherwise.
  virtual std::string variant() const { return {}; }
  // Why the last reset left the solver unable to step (it then steps nothing); empty when fine.
  virtual std::string failure() const = 0;
  // Blocks until the work already issued is done, so wall-clock timing is honest.
  virtual void finish() {}

  // Measures the state at the end of the last frame without waiting for it: the GPU solver
  // reduces it on the GPU to a few numbers per work group and copies them behind a fence; the
  // CPU solvers measure at once. Samples come back in the order they were asked for.
  virtual void requestSample(long frame) = 0;
  // The oldest sample asked for, once ready; with `wait`, waiting for it. Nothing when none is
  // asked for or, without `wait`, none is ready yet.
  virtual std::optional<FrameSample> takeSample(bool wait) = 0;
  // Forgets samples asked for and not taken (after a reset).
  virtual void dropSamples() = 0;
  // Contact measures in every mode: where hair-hair is off, each sampled frame also runs the
  // candidate search on its end state, outside the frame's timing, for the measures alone
  // (pairs, penetration depth, crossings between samples). Off by default: it costs a
  // candidate search per sample. Solvers without contacts ignore it.
  virtual void setContactMeasures(bool always) { (void)always; }

  // Time per stage of the last frame; solvers that cannot time stages return what they have.
  virtual std::vector<StageTime> stageTimes() { return {}; }
  // The stiffness it runs with: steps per frame, alpha, windows (CSM solvers).
  virtual StiffnessInfo stiffness() const { return {}; }
  // The memory its scene holds on the device, by kind (empty: not counted; the CPU solvers'
  // is the process's, which the metrics give as its peak resident size).
  virtual MemoryUse memoryUse() const { return {}; }

 protected:
  ~SolverDiagnostics() = default;
};

// Makes a solver of one kind, ready for reset (tests, benchmarks and measures run scenes on it).
using SolverMaker = std::function<std::unique_ptr<Solver>()>;

}  // namespace csm
