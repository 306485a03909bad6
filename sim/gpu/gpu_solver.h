// Chain Shape Matching on the GPU: the step of DESIGN.md section 1 in GLSL compute shaders
// (shaders/sim/), the same math in the same order as CpuSolver, in float. Everything stays
// on the GPU; nothing is read back inside a frame.
//
// Per step (substep): predict.comp (per particle), shape_match.comp (per strand: region
// sums, rotations, goals, integration), strain_limit.comp (per strand). The regions and the
// number of steps come from sim/stiffness.h, as for CpuSolver. Per frame, when
// collision.mode is full: the hash grid by counting sort (grid_count, a three-level parallel
// scan of the buckets and one of the segments, grid_scatter; DESIGN.md section 1.7),
// contacts.comp per grid entry and segment_forces.comp, whose per-segment forces the next
// frame's predict passes gather. 3 dispatches per step + 11 per frame.
#pragma once

#include <array>
#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/query.h"
#include "gl/buffer_texture.h"
#include "gl/fence.h"
#include "sim/gpu/gpu_params.h"
#include "sim/hair_state.h"
#include "sim/solver.h"

namespace csm {

class GpuSolver final : public Solver {
 public:
  // Needs a current GL 4.3 context; compiles the shaders. Null, with the compiler's log in
  // `error`, when they do not build.
  static std::unique_ptr<GpuSolver> create(std::string* error);
  ~GpuSolver() override;

  std::string_view name() const override { return "gpu"; }
  void reset(const Groom& groom, const Config& config, const Pose& head) override;
  void setConfig(const Config& config) override;
  void stepFrame(const Pose& from, const Pose& to) override;

  size_t strandCount() const override { return strands_; }
  size_t particleCount() const override { return particles_; }
  double time() const override { return time_; }

  void finish() override;
  void readPositions(std::vector<glm::vec4>& out) override;
  void readVelocities(std::vector<glm::vec4>& out) override;
  void writeState(const std::vector<glm::vec4>& positions,
                  const std::vector<glm::vec4>& velocities) override;
  unsigned positionBuffer() override { return position_.id(); }
  std::vector<StageTime> stageTimes() override;
  // Those of the latest sample taken: nothing is read back for them.
  ContactStats contactStats() override { return sampledContacts_; }
  void requestSample(long frame) override;
  std::optional<FrameSample> takeSample(bool wait = false) override;
  void dropSamples() override;
  StiffnessInfo stiffness() const override { return describeStiffness(regions_, config_.sim); }

  // --- For tests and tools (these read back at once). ---
  // The contacts of the last collision pass; also grows the grid when it did not fit.
  ContactStats readContactStats();
  // Runs the collision pass on the current state now (stepFrame does it at the end of each
  // frame when collision.mode is full); its forces act during the next frame.
  void detectContacts();
  // Records the contact pairs (a < b) the collision pass finds, up to `capacity` (0: off).
  void setPairCapacity(size_t capacity);
  // The pairs of the last collision pass, in no particular order; `overflow` when there were
  // more than the capacity.
  std::vector<std::pair<uint32_t, uint32_t>> readContactPairs(bool* overflow = nullptr);
  // Per segment (by its first particle): the contacts it summed, both sides counted.
  std::vector<uint32_t> readSegmentContactCounts();
  // Hash table size of the grid (a power of two).
  uint32_t bucketCount() const { return buckets_; }
  // The grid of the last collision pass (reads back): entries it needed, entries the buffers
  // hold (over it, the pass applied no forces), segments in no cell (not finite, or a box
  // over the cell cap), and the cell edge in metres.
  struct GridStats {
    uint32_t entries = 0, capacity = 0, oversize = 0, buckets = 0;
    float cell = 0.0f;
  };
  GridStats gridStats();

 private:
  GpuSolver() = default;
  bool build(int maxStrandSize, std::string* error);
  void uploadRegions();
  void writeParams(const std::vector<Pose>& poses, const std::vector<Pose>& before);
  void bindAll();
  void collide();
  void growEntries(uint64_t needed);
  void scan(uint32_t blocks);
  static void view(gl::BufferTexture& tex, const gl::Buffer& buffer, GLenum format);
  void dispatchItems(const gl::Program& program, uint32_t items, uint32_t groupSize);
  void timeStage(int stage);
  void afterCounters(const uint32_t* counters);
  void endStage();
  void beginTimerFrame();

  Config config_;
  double time_ = 0.0;
  Pose head_;
  HairState state_;  // the layout the regions are built from
  Regions regions_;
  size_t particles_ = 0, strands_ = 0;
  uint32_t segments_ = 0;
  uint32_t buckets_ = 0, scanBlocks_ = 0;
  uint32_t segmentScan_ = 0;    // counts in the per-segment scan (a power of two)
  uint32_t entryCapacity_ = 0;  // grid entries the entry buffers hold
  double meanSegment_ = 0.0;    // mean rest length of a segment (m)
  size_t pairCapacity_ = 0;
  bool forcesValid_ = false;
  bool collidedThisFrame_ = false;
  int builtMaxN_ = 0;
  gpu::SimParams params_{};

  struct Programs {
    gl::Program predict{gl::NoCreate}, shapeMatch{gl::NoCreate}, strainLimit{gl::NoCreate};
    gl::Program gridCount{gl::NoCreate}, scanBlocks{gl::NoCreate}, scanSums{gl::NoCreate},
        scanAdd{gl::NoCreate}, gridScatter{gl::NoCreate}, contacts{gl::NoCreate},
        segmentForces{gl::NoCreate}, measure{gl::NoCreate};
  } programs_;

  gl::Buffer rest_{gl::NoCreate}, position_{gl::NoCreate}, velocity_{gl::NoCreate},
      strandFirst_{gl::NoCreate}, particleStrand_{gl::NoCreate}, predicted_{gl::NoCreate},
      rotation_{gl::NoCreate}, strandOrder_{gl::NoCreate}, paramsBuffer_{gl::NoCreate},
      spheres_{gl::NoCreate}, segmentForce_{gl::NoCreate}, gridCount_{gl::NoCreate},
      gridStart_{gl::NoCreate}, scanBlockSums_{gl::NoCreate}, entryLow_{gl::NoCreate},
      entryHigh_{gl::NoCreate}, counters_{gl::NoCreate}, pairs_{gl::NoCreate},
      segmentContacts_{gl::NoCreate}, segmentCells_{gl::NoCreate}, segmentBase_{gl::NoCreate},
      segmentScanBlocks_{gl::NoCreate}, partialForce_{gl::NoCreate}, region_{gl::NoCreate},
      strandStiffness_{gl::NoCreate}, measure_{gl::NoCreate};
  // texelFetch views for reads that differ per invocation (see gl/buffer_texture.h).
  gl::BufferTexture positionTex_{gl::NoCreate}, velocityTex_{gl::NoCreate}, restTex_{gl::NoCreate},
      entryLowTex_{gl::NoCreate}, gridStartTex_{gl::NoCreate}, entryHighTex_{gl::NoCreate},
      predictedTex_{gl::NoCreate}, regionTex_{gl::NoCreate};

  // GPU time per stage: one GL_TIME_ELAPSED query around each dispatch group, for the last
  // few frames; stageTimes() reads the newest frame whose results are in, never waiting. Software
  // drivers (llvmpipe) run a dispatch before glDispatchCompute returns and report no time for it in
  // their timer queries, so there the stages are timed by the CPU clock instead.
  static constexpr int kStages = 5;  // integrate, shape_matching, strain_limiting, grid, contacts
  struct FrameTimers {
    std::vector<std::pair<int, gl::Query>> queries;
    size_t used = 0;
    bool issued = false;
    std::array<double, kStages> cpuMs{};  // software drivers
  };
  bool cpuTiming_ = false;
  int openStage_ = -1;
  std::chrono::steady_clock::time_point stageStart_;
  std::array<FrameTimers, 3> timers_;
  int timerFrame_ = 0;
  std::vector<StageTime> lastStages_;

  // Samples (requestSample): the measure pass's records and the counters copied into a staging
  // buffer of a small ring, read once its fence has passed. A full ring waits for its oldest.
  struct SampleSlot {
    gl::Buffer staging{gl::NoCreate};
    gl::Fence fence;
    long frame = -1;
    uint32_t groups = 0;
  };
  static constexpr int kSampleSlots = 4;
  std::array<SampleSlot, kSampleSlots> slots_;
  std::deque<int> pendingSlots_;   // oldest first
  std::deque<FrameSample> ready_;  // read off a full ring, not taken yet
  FrameSample readSlot();          // the oldest pending slot, whose fence has passed
  int lastSubsteps_ = 1;
  ContactStats sampledContacts_;
};

}  // namespace csm
