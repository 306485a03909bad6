// One interface for every solver: the CPU reference (sim/cpu), the GPU solver (sim/gpu) and
// the baselines used by the benchmarks.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec4.hpp>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/core/pose.h"
#include "sim/core/results.h"

namespace csm {

class HeadModel;  // sim/head/head_model.h

// Everything a solver's next frames depend on, as bytes in the solver's own precision
// (positions, velocities, each region's rotation, its clock and head): restored, the solver
// runs on exactly as it did from there (the viewer's timeline, sim/run/frame_recording.h).
struct SolverState {
  std::vector<std::byte> bytes;
};

// A copy of the frame a solver is at, made where its state lives and read once it has arrived
// (Solver::copyFrame): the GPU solver copies into a staging buffer behind a fence, so nothing
// waits for the GPU until read(), and read() only when the GPU has not got there yet.
class FrameCopy {
 public:
  virtual ~FrameCopy() = default;
  // Whether read() would return without waiting.
  virtual bool ready() const = 0;
  // The positions (xyz a particle) and, when the copy was asked with the state, the solver's
  // state as saveState would have written it then (into `state` when given).
  virtual void read(std::vector<glm::vec3>& positions, SolverState* state) = 0;
};

class Solver {
 public:
  virtual ~Solver() = default;
  virtual std::string_view name() const = 0;
  // How it runs, where it has a choice (the GPU solver: its kernel path); empty otherwise.
  virtual std::string variant() const { return {}; }

  // Rebuilds everything from a groom: positions at rest under `head`, zero velocities.
  virtual void reset(const Groom& groom, const Config& config, const Pose& head) = 0;
  // The head the next resets collide with, built once by whoever loaded the scene (Simulation:
  // sim/head/head_model.h). A solver never handed one builds its own from each reset's config.
  virtual void setHead(std::shared_ptr<const HeadModel> head) { (void)head; }
  // Live parameters; takes effect on the next step.
  virtual void setConfig(const Config& config) = 0;
  // One frame of config.sim.dt seconds, the head moving from `from` to `to`: sim.substeps steps,
  // or with the calibrated stiffness model as many as planFrame (sim/solver/stiffness.h) asks.
  virtual void stepFrame(const Pose& from, const Pose& to) = 0;

  virtual size_t strandCount() const = 0;
  virtual size_t particleCount() const = 0;
  virtual double time() const = 0;

  // Blocks until the work already issued is done, so wall-clock timing is honest.
  virtual void finish() {}

  // Measures the state at the end of the last frame without waiting for it: the GPU solver
  // reduces it on the GPU to a few numbers per work group and copies them behind a fence; the
  // CPU solvers measure at once. Samples come back in the order they were asked for.
  virtual void requestSample(long frame) = 0;
  // The oldest sample asked for, once ready; with `wait`, waiting for it. Nothing when none is
  // asked for or, without `wait`, none is ready yet.
  virtual std::optional<FrameSample> takeSample(bool wait = false) = 0;
  // Forgets samples asked for and not taken (after a reset).
  virtual void dropSamples() = 0;

  // Read-backs of the whole state, for tests, export and the CPU renderer path; the frame
  // loop samples instead (requestSample).
  virtual void readPositions(std::vector<glm::vec4>& out) = 0;
  virtual void readVelocities(std::vector<glm::vec4>& out) = 0;
  // Replaces positions and velocities (the layout readPositions gives); the rest of the
  // solver's state (region rotations, contact forces) stays. For tests, and to resume a state.
  virtual void writeState(const std::vector<glm::vec4>& positions,
                          const std::vector<glm::vec4>& velocities) = 0;
  // Saves, and restores, what the next frames depend on. The default keeps the read-backs
  // (float) and the clock; the CSM solvers keep their whole state, so that a restored solver
  // steps to the same bits. restoreState fails (false, *error set) for a state of another
  // scene (another particle count).
  virtual void saveState(SolverState& out);
  virtual bool restoreState(const SolverState& in, std::string* error);
  // The frame as it stands, for a reader that can take it a few frames later (the viewer's
  // recording): the positions, and with `withState` what saveState saves. This default reads
  // back at once.
  virtual std::unique_ptr<FrameCopy> copyFrame(bool withState);
  // Moves the whole hair rigidly by `by` (positions, velocities and whatever rotations the
  // solver keeps), and the head where the last frame left it, as if the hair were fixed to the
  // head: what a head that jumps does to it (Simulation::stepFrame). This default moves the
  // particles only, through the read-backs.
  virtual void carry(const Pose& by);

  // The GL name of an SSBO holding the current positions (vec4 per particle, in particle
  // order) when the solver keeps them on the GPU; 0 when the caller must upload readPositions.
  virtual unsigned positionBuffer() { return 0; }

  // Time per stage of the last frame; solvers that cannot time stages return what they have.
  virtual std::vector<StageTime> stageTimes() { return {}; }
  // Hair-hair contacts of the last collision pass (zeros when collisions are off). The GPU
  // solver's are those of its latest sample: it reads nothing back for them.
  virtual ContactStats contactStats() { return {}; }
  // Contact measures in every mode: where hair-hair is off, each sampled frame also runs the
  // candidate search on its end state, outside the frame's timing, for the measures alone
  // (pairs, penetration depth, crossings between samples). Off by default: it costs a
  // candidate search per sample. Solvers without contacts ignore it.
  virtual void setContactMeasures(bool always) { (void)always; }
  // The stiffness it runs with: steps per frame, alpha, windows (CSM solvers).
  virtual StiffnessInfo stiffness() const { return {}; }
  // The memory its scene holds on the device, by kind (empty: not counted; the CPU solvers'
  // is the process's, which the metrics give as its peak resident size).
  virtual MemoryUse memoryUse() const { return {}; }
  // Why the last reset left the solver unable to step (it then steps nothing); empty when fine.
  virtual std::string failure() const { return {}; }
};

// Makes a solver of one kind, ready for reset (tests, benchmarks and measures run scenes on it).
using SolverMaker = std::function<std::unique_ptr<Solver>()>;

}  // namespace csm
