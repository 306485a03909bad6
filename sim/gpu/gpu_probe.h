// What tests and tools read of the GPU solver, and the knobs they turn, at once (each read-back
// a GPU stall): the candidate search's lists, counters and grid, the volume's nodes, the
// passes in use. The frame loop never calls these (it samples behind fences,
// sim/gpu/sample_ring.h), so they stay off GpuSolver's interface; the probe is its friend.
//   GpuProbe(*gpu).gridStats()
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "sim/core/results.h"
#include "sim/gpu/gpu_solver.h"

namespace csm {

class GpuProbe {
 public:
  explicit GpuProbe(GpuSolver& solver) : solver_(solver) {}

  // The measures of the last candidate list (reading them changes nothing: the grid grows as
  // the next frame begins).
  ContactStats readContactStats() const;
  // Builds the candidate list of the current state now (stepFrame does it at the start of
  // each frame with strand contacts); the next frame builds its own.
  void detectContacts();
  // Caps the collision grid's growing buffers at `bytes` each, as a device whose buffer
  // textures hold no more (ContactSearch::limitStorage): the next reset sizes them under it,
  // and a frame after the cap is raised may grow them past it.
  void limitGridStorage(uint64_t bytes);
  // Where the second view of the sides and lists starts, at most (ContactSearch::limitListSplit).
  void limitGridListSplit(uint64_t texels);
  uint32_t gridListSplit() const;
  // The pairs (a < b) closer than 2r of the last candidate pass, in no particular order;
  // `overflow` when the pair list did not hold them.
  std::vector<std::pair<uint32_t, uint32_t>> readContactPairs(bool* overflow = nullptr) const;
  // Per segment (by its first particle): its candidates (other segment, contact distance).
  std::vector<std::vector<std::pair<uint32_t, float>>> readCandidates() const;
  // The order the list pass and the contact solve take the segments in (segment_order.comp).
  std::vector<uint32_t> readSegmentOrder() const;
  // The grid of the last candidate pass: entries it needed, entries the buffers hold (over it,
  // the frame kept the last list), segments in no cell (not finite, or a box over the cell
  // cap), and the cell edge in metres.
  struct GridStats {
    uint32_t entries = 0, capacity = 0, oversize = 0, buckets = 0;
    uint32_t pairs = 0, pairCapacity = 0;  // candidate pairs the last pass needed, and held
    float cell = 0.0f;
  };
  GridStats gridStats() const;
  // Nodes of the volume mode's grid: none unless collision.mode is a volume mode.
  size_t volumeNodes() const;
  // Nodes the volume's node pass ran on in the last frame: the box the splat reached (reads
  // back its indirect dispatch).
  size_t volumeNodesVisited() const;
  // The passes in use: chosen at create() by the context (PerStrand on a software renderer,
  // PerParticle on a GPU); CSM_GPU_KERNELS=strand|particle in the environment overrides, and
  // so does setKernels, which builds what the choice needs.
  GpuKernels kernels() const;
  bool setKernels(GpuKernels kernels, std::string* error = nullptr);

 private:
  GpuSolver& solver_;
};

}  // namespace csm
