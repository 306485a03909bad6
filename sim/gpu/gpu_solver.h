// Chain Shape Matching on the GPU: the step of METHOD.md section 2 in GLSL compute shaders
// (shaders/sim/), the same math in the same order as CpuSolver, in float. Everything stays
// on the GPU; nothing is read back inside a frame.
//
// The pieces: StrandBuffers (the hair's state and layout), the passes of a step (GpuKernels:
// per strand, predict.comp, shape_match.comp and strain_limit.comp; per particle, strand_step.comp
// and, with strand contacts, strand_strain.comp), ContactSearch (hair-hair contacts once per frame
// when collision.mode is full, acting during the next frame; ContactSolve, their solve each
// substep), VolumePasses (the volume modes' grid, once a frame), SampleRing (the measures,
// fenced and read a few frames late) and StageTimer. The regions and the number of steps come
// from sim/solver/stiffness.h, as for CpuSolver. 3 dispatches per step (1 per particle without
// strand contacts) + 11 per frame.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gl/buffer.h"
#include "sim/gpu/contact_search.h"
#include "sim/gpu/compute_pass.h"
#include "sim/gpu/contact_solve.h"
#include "sim/gpu/gpu_params.h"
#include "sim/gpu/sample_ring.h"
#include "sim/gpu/stage_timer.h"
#include "sim/gpu/strand_buffers.h"
#include "sim/gpu/volume_passes.h"
#include "sim/core/hair_state.h"
#include "sim/head/distance_grid.h"
#include "sim/head/head_model.h"
#include "sim/core/solver.h"

namespace csm {

// Which passes step the hair. PerStrand: one invocation a strand (predict.comp per particle,
// then shape_match.comp and strain_limit.comp per strand), each invocation's sums in private
// arrays: what a CPU rasterizer (llvmpipe) runs fastest, its SIMD lanes each a strand. PerParticle:
// one invocation a particle, whole strands to a work group (strand_step.comp, strand_strain.comp):
// sums as scans in shared memory, the strain limit's sweep over the strand held there, predict,
// shape matching and (without strand contacts) the strain limit in one pass; what a GPU runs
// fastest (a strand's loads contiguous, every lane busy, no private arrays in local memory).
enum class GpuKernels { PerStrand, PerParticle };
const char* gpuKernelsName(GpuKernels k);

class GpuSolver final : public Solver, public SolverState, public SolverDiagnostics {
 public:
  // Needs a current GL 4.3 context; compiles the shaders. Null, with the compiler's log in
  // `error`, when they do not build.
  static std::unique_ptr<GpuSolver> create(std::string* error);
  // The same, after checking that a context is current and runs GL 4.3 compute shaders: null
  // with a message that says what to do instead (--solver cpu) otherwise.
  static std::unique_ptr<GpuSolver> start(std::string* error);
  ~GpuSolver();

  // Solver (gpu_solver.cpp)
  std::string_view name() const override { return "gpu"; }
  void setHead(std::shared_ptr<const HeadModel> head) override { headModel_.hand(std::move(head)); }
  void reset(const Groom& groom, const Config& config, const Pose& head) override;
  void setConfig(const Config& config) override;
  using Solver::stepFrame;
  void stepFrame(const FramePath& path) override;
  SolverCounts counts() const override { return {hair_.strands, hair_.particles}; }
  double time() const override { return time_; }
  SolverState& state() override { return *this; }
  SolverDiagnostics& diagnostics() override { return *this; }

  // SolverState (gpu_solver_state.cpp)
  void readPositions(std::vector<glm::vec4>& out) override;
  void readVelocities(std::vector<glm::vec4>& out) override;
  void write(const std::vector<glm::vec4>& positions,
             const std::vector<glm::vec4>& velocities) override;
  void save(SavedState& out) override;
  bool restore(const SavedState& in, std::string* error) override;
  // Positions (and velocities and rotations with the state) copied on the GPU into a staging
  // buffer behind a fence: no wait now, none in read() once the fence has passed.
  std::unique_ptr<FrameCopy> copyFrame(bool withState) override;
  void carry(const Pose& by) override;
  unsigned positionBuffer() override { return hair_.position.id(); }

  // SolverDiagnostics (gpu_solver_diagnostics.cpp)
  std::string variant() const override { return gpuKernelsName(kernels_); }
  std::string failure() const override { return failure_; }
  void finish() override;
  void requestSample(long frame) override;
  std::optional<FrameSample> takeSample(bool wait) override;
  void dropSamples() override { samples_.drop(); }
  void setContactMeasures(bool always) override;
  std::vector<StageTime> stageTimes() override { return timer_.times(); }
  StiffnessInfo stiffness() const override {
    return describeStiffness(regions_, config_.sim, dftlOf(config_));
  }
  MemoryUse memoryUse() const override;

 private:
  // Tests and tools read the buffers, and choose the passes, through it (sim/gpu/gpu_probe.h).
  friend class GpuProbe;

  // How the step's passes read: on a GPU the parameters from a uniform block and the particles
  // through storage blocks; on a software renderer from storage and texel fetches.
  struct Reads {
    bool uniformParams = false;  // CSM_PARAMS_UNIFORM
    bool storage = false;        // CSM_STORAGE_READS
  };
  GpuSolver(bool cpuClock, GpuKernels kernels, Reads reads);
  // `defines` and those of reads_.
  std::vector<gl::Define> withReads(std::vector<gl::Define> defines) const;
  bool build(int maxStrandSize, std::string* error);
  void uploadRegions();
  // Whether frames or samples list candidates (a strand mode, or contact measures).
  bool listsCandidates() const;
  // The grid's buffers sized for the hair as it stands (ContactSearch::sizeForLastSearch).
  void sizeLists();
  // The strands a search takes: every strand with strand contacts, else the measures' sample
  // (sim/core/measure_sample.h).
  uint32_t searchStride() const;
  // The contact buffers reserved for searchStride's strands, when not yet or for others.
  void reserveLists();
  // The frame's parameters for steps ending at `poses` (from `before`), written into params_
  // by what they fill, then uploaded with a Substep per step.
  // Each step's head pose and the head's where the step starts, and the torso's (empty: torso_
  // throughout).
  void writeParams(const std::vector<Pose>& poses, const std::vector<Pose>& before,
                   const std::vector<Pose>& torso = {}, const std::vector<Pose>& torsoBefore = {});
  void writeStepParams(gpu::SimParams& p) const;  // gravity, wind, stiffness, the counts
  void writeHeadParams(gpu::SimParams& p) const;  // the hair's radius, the head's shape
  // Strand contacts and their grid, whose cells count from the head where the frame ends.
  void writeContactParams(gpu::SimParams& p, const Pose& frameEnd) const;
  // params_ and each step's Substep (the head's pose, its spheres) to the GPU.
  void uploadParams(const std::vector<Pose>& poses, const std::vector<Pose>& before,
                    const std::vector<Pose>& torso, const std::vector<Pose>& torsoBefore);
  void bindAll();
  // The candidate lists of the current state, built now (GpuProbe::detectContacts, the
  // measures).
  void listCandidatesNow(gpu::StageTimer* timer);
  // A candidate list within the frame (collision.lists), from where the hair is now.
  void listAgain();
  unsigned lastSubstepSpheres() const;  // the first sphere of the last step's
  void uploadHeadField();               // the head's distance field, when it is one

  Config config_;
  SolverHead headModel_;  // the scene's head, handed before the reset
  SceneHead shape_;       // what it collides with, read every step
  double time_ = 0.0;
  Pose head_;
  Pose torso_;               // the torso's pose where the last frame ended
  HairState state_;          // the layout the regions are built from
  double meanWeight_ = 1.0;  // of state_.weight (contactRadius)
  Regions regions_;
  bool builtCommon_ = false;   // the passes both paths use
  int builtMaxN_ = 0;          // the per-strand passes', 0 until built
  int builtParticleMaxN_ = 0;  // the per-particle passes', 0 until built
  GpuKernels kernels_ = GpuKernels::PerStrand;
  Reads reads_;
  // Set by reset when the groom's strands cannot be simulated, or no head was handed.
  std::string failure_;
  gpu::SimParams params_{};

  struct Passes {
    gpu::ComputePass predict, shapeMatch, measure, carry;
    // For the head's spheres and for its distance field (llvmpipe runs both sides of a
    // branch: each build runs only its own head's push).
    gpu::ComputePass strainLimit[2];
    // The per-particle path: the step without the sweep (strand contacts), with it (per head),
    // and the sweep alone after the contacts (per head).
    gpu::ComputePass strandStep, strandStepSweep[2], strandStrain[2];
  } passes_;
  gpu::StrandBuffers hair_;
  gpu::ContactSearch contactSearch_;  // strand contacts: the search
  gpu::ContactSolve contactSolve_;    // and the solve
  glm::vec3 resetOrigin_{0.0f};       // the head's place at the reset (reserveLists' cells)
  gl::Buffer paramsBuffer_{gl::NoCreate}, spheres_{gl::NoCreate}, measure_{gl::NoCreate};
  gpu::VolumePasses volume_;  // the volume mode's grid and passes
  // The head's distance field (sim/head/distance_grid.h), read by texel fetches; one node when
  // unused.
  gl::Buffer headField_{gl::NoCreate};
  gl::BufferTexture headFieldTex_{gl::NoCreate};
  const DistanceGrid* uploadedField_ = nullptr;
  const DistanceGrid* uploadedTorso_ = nullptr;    // after the head's nodes in headField_
  std::shared_ptr<const HeadModel> uploadedHead_;  // the model uploadedField_ belongs to
  int substepsWritten_ = 0;                        // steps of the last writeParams
  gpu::StageTimer timer_;
  bool measureContacts_ = false;
  // With hair-hair off and the measures on: frames stepped since the last measure search (1:
  // the grid's counters measure where this frame started).
  int framesSinceMeasure_ = 2;
  void measureNow();   // searches where the hair stands
  void measureAnew();  // after a reset, a restore or new settings (the lists already forgotten)
  gpu::SampleRing samples_;
};

}  // namespace csm
