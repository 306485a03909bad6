// Hair-hair contacts on the GPU (DESIGN.md section 1.7): a hash grid of segment boxes built by
// counting sort (grid_count, a three-level parallel scan of the buckets and one of the
// segments' cell counts, grid_scatter), contacts.comp per grid entry and segment_forces.comp,
// whose per-segment forces the next frame's predict passes gather. Its capacity follows what
// the samples' counters report it needed; a frame over capacity applies no hair-hair forces
// and says so in the counters (entries needed > capacity).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gl/buffer.h"
#include "gl/buffer_texture.h"
#include "sim/gpu/compute_pass.h"
#include "sim/gpu/gpu_params.h"
#include "sim/gpu/stage_timer.h"
#include "sim/solver.h"

namespace csm::gpu {

class CollisionGrid {
 public:
  bool build(std::string* error);
  // Sizes the grid for `segments` segments over `particles` particles, mean rest length
  // `meanSegment` (m); clears the counters and forces.
  void reset(size_t particles, uint32_t segments, double meanSegment);
  // The grid's part of the parameters: counts.w, grid, cells.
  void writeParams(SimParams& p, float radius) const;
  void bind() const;
  // One collision pass on the bound state, timed as the grid and contacts stages.
  void run(StageTimer& timer);
  void clearCounters() { counters_.clearToZero(); }
  // Grows the entry buffers when `counters` (read back) say they did not fit; true if it grew.
  bool countersSeen(const uint32_t* counters);

  const gl::Buffer& counters() const { return counters_; }
  uint32_t entryCapacity() const { return entryCapacity_; }
  uint32_t bucketCount() const { return buckets_; }

  // --- Read back at once, for tests and tools. ---
  std::vector<uint32_t> readCounters() const;
  void setPairCapacity(size_t capacity);
  std::vector<std::pair<uint32_t, uint32_t>> readPairs(bool* overflow) const;
  std::vector<uint32_t> readSegmentContactCounts() const;

 private:
  void growEntries(uint64_t needed);
  void scan(uint32_t blocks);

  size_t particles_ = 0;
  uint32_t segments_ = 0;
  double meanSegment_ = 0.0;
  uint32_t buckets_ = 0, scanBlocks_ = 0;
  uint32_t segmentScan_ = 0;    // counts in the per-segment scan (a power of two)
  uint32_t entryCapacity_ = 0;  // grid entries the entry buffers hold
  size_t pairCapacity_ = 0;

  struct Passes {
    ComputePass count, scanBlocks, scanSums, scanAdd, scatter, contacts, segmentForces;
  } passes_;
  gl::Buffer segmentForce_{gl::NoCreate}, gridCount_{gl::NoCreate}, gridStart_{gl::NoCreate},
      scanBlockSums_{gl::NoCreate}, entryLow_{gl::NoCreate}, entryHigh_{gl::NoCreate},
      counters_{gl::NoCreate}, pairs_{gl::NoCreate}, segmentContacts_{gl::NoCreate},
      segmentCells_{gl::NoCreate}, segmentBase_{gl::NoCreate}, segmentScanBlocks_{gl::NoCreate},
      partialForce_{gl::NoCreate};
  gl::BufferTexture entryLowTex_{gl::NoCreate}, entryHighTex_{gl::NoCreate},
      gridStartTex_{gl::NoCreate};
};

}  // namespace csm::gpu
