// Strand contacts on the GPU (DESIGN.md section 1.7; sim/solver/contacts.h is the CPU reference).
// Once per frame, the candidates: a hash grid of segment boxes built by counting sort
// (grid_count, a three-level parallel scan of the buckets, grid_scatter); candidates.comp per
// grid entry lists the pairs, each once; a counting sort by segment (the same scan over each
// segment's pair count, pair_scatter) and candidate_lists.comp per segment give every segment
// its sorted list. The passes over entries and pairs are dispatched indirectly, sized on the
// GPU by what the frame has (dispatch_size.comp): a generous capacity costs memory, not time. Every
// substep, contact_solve.comp: each segment's corrections, which strain_limit.comp applies. The
// grid's and the pair list's capacities are sized at reset for a search of the hair as it
// stands (sizeForLastSearch), then follow what the last search needed: its counters are
// copied behind a fence as it ends and read as the next one begins (beginFrame), so the buffers
// grow at the same search whatever the GPU's timing and whoever reads the samples (the
// simulation stays deterministic). A search over either capacity keeps each segment's list from
// the search before (its pairs, evaluated where the hair is now; none after a reset or a growth
// of the pair list) and says so in the counters (entries or pairs needed > capacity), and the
// running count of such searches (CSM_COUNTER_OVERFLOWS, ContactStats::overflows) reaches the
// metrics and the panel.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/buffer.h"
#include "gl/buffer_texture.h"
#include "gl/fence.h"
#include "sim/gpu/compute_pass.h"
#include "sim/gpu/gpu_params.h"
#include "sim/gpu/stage_timer.h"
#include "sim/core/solver.h"

namespace csm::gpu {

// The contact measures in a counters buffer (CSM_COUNTER_*).
ContactStats contactStatsOf(const uint32_t* counters);

class CollisionGrid {
 public:
  bool build(std::string* error);
  // Sizes the grid for `segments` segments over `particles` particles, mean rest length
  // `meanSegment` (m); clears the counters and lists. reserveFor then sizes the entries.
  void reset(size_t particles, uint32_t segments, double meanSegment);
  // Sizes the entry buffer for the boxes of `position` (a state the coming frames start near,
  // the head at `origin`) with candidate distance `reach`, and half again, and the pair list
  // as large. Every cell of a box counts, so this bounds the clipped entries the grid makes
  // (Fig. 1: ~1.5x them): they then rarely need to grow while the hair moves (a frame over them
  // keeps the lists before it, says so in the counters, and the next frame grows them).
  void reserveFor(std::span<const glm::vec4> position, std::span<const uint32_t> strand,
                  float reach, const glm::vec3& origin);
  // After a search of the hair as it stands (a reset's, not inside a step): reads it back at
  // once, sizes the entries and the pair list a quarter over what it needed, and forgets it
  // (counters and lists as after reset). Dense hair needs more pairs per entry than
  // reserveFor allows (Fig. 1 at 100,000 strands: its first frame overflowed); the first frame
  // then fits.
  void sizeForLastSearch();
  // Before a frame's writeParams: the buffers grow to what the last search needed (waiting for
  // it to end on the GPU, which it has unless the CPU runs far ahead); the lists swap buffers
  // (this frame's becomes last frame's);
  // `contacts` says whether this frame builds them (when the last one did not, there is no
  // last list to count crossings against; when this one does not, the last one's measures
  // are cleared, once, on the GPU).
  void beginFrame(bool contacts);
  // The grid's part of the parameters: grid, cells.
  void writeParams(SimParams& p, float reach) const;
  void bind() const;
  // The frame's candidates from the bound state, timed as the grid stage (timer null:
  // untimed). `measured`: the frame's first list, whose counters measure the state; a list
  // within the frame (collision.lists) counts only its crossings against the list before
  // it, its oversize and crowded segments, and its overflow.
  void findCandidates(StageTimer* timer, bool measured = true);
  // Before a list within the frame: this frame's list becomes the last one (crossings are
  // counted against it), as at beginFrame but with nothing grown or cleared. The caller
  // writes the parameters again (their grid half) and binds the grid.
  void swapLists() { half_ ^= 1u; }
  // One substep's corrections (the timer's stage is the caller's): `iterations` contact solves,
  // each but the last applied to the positions and velocities of the `strands` here, the
  // last one left for the strain-limit sweep.
  void solve(unsigned substep, int iterations, uint32_t strands);
  // Grows the entry buffer or the pair list when `counters` (read back) say they did not fit;
  // true if either grew. beginFrame calls it with the last search's counters; a tool that reads
  // them at once may too (GpuSolver::detectContacts).
  bool countersSeen(const uint32_t* counters);

  const gl::Buffer& counters() const { return counters_; }
  // The indirect dispatch sizes (CSM_DISPATCH_*), bound at CSM_BIND_DISPATCH with the grid;
  // the volume's node pass keeps its own slot there.
  const gl::Buffer& dispatch() const { return dispatch_; }
  uint32_t entryCapacity() const { return entryCapacity_; }
  uint32_t pairListCapacity() const { return pairListCapacity_; }
  // Caps the buffers that grow with the hair's density (the entries, the pair list, its sides
  // and the lists) at `bytes` each, as a device whose buffer textures hold no more; tests use
  // it to reach the cap with a small scene. A frame that needs more than the capped buffers
  // hold keeps the last list and says so, as any frame over them. Set before reset, it caps
  // what the reset sizes; raised later (UINT64_MAX: the device's own limit), the buffers grow
  // as the next frame begins, as after any overflow. (The storage buffers sized by the
  // particles stay under 128 MiB up to ~4 M particles.)
  void limitStorage(uint64_t bytes);
  // Caps the texels of the first view of the sides and of the lists at `texels` (as on a
  // device whose buffer textures hold no more), before reset; tests use it to put a small
  // scene's lists across both views.
  void limitListSplit(uint64_t texels);
  uint32_t listSplit() const { return listSplit_; }
  uint32_t bucketCount() const { return buckets_; }

  // --- Read back at once, for tests and tools. ---
  std::vector<uint32_t> readCounters() const;
  std::vector<std::pair<uint32_t, uint32_t>> readPairs(bool* overflow) const;
  // This frame's candidates of each segment (other segment, contact distance), as
  // findCandidates lists them.
  std::vector<std::vector<std::pair<uint32_t, float>>> readCandidates() const;
  // Which segment each invocation of the list pass and the contact solve takes: the segments
  // of each run of CSM_PARTICLE_GROUP by candidate count, most first, ties by index.
  std::vector<uint32_t> readSegmentOrder() const;

 private:
  void growEntries(uint64_t needed);
  void growPairList(uint64_t needed);
  // The most entries and candidate pairs the buffers may take on this device.
  uint64_t entryLimit() const;
  uint64_t pairLimit() const;
  // The last search's counters, copied when it ended: grows the buffers to what it needed.
  void growFromLastSearch();
  // listSplit_ from the texels a view holds, and the passes' uniform; true.
  bool setListSplit();
  // Both builds of a pass that reads or writes the sides or the lists.
  static bool buildSplit(ComputePass (&pass)[2], const char* path, std::string* error);
  // Whether the sides and the lists run past their first view (the passes' second build).
  bool splitViews() const { return 2 * uint64_t(pairListCapacity_) > listSplit_; }
  // Sizes dispatch slot `slot` (CSM_DISPATCH_*) for the items counter `counter` holds (at
  // most `capacity`), in groups of `groupSize`.
  void dispatchFor(uint32_t counter, uint32_t capacity, uint32_t groupSize, uint32_t slot);
  // Zeroes this frame's counters (not the running count of frames over capacity).
  void clearFrameCounters();
  double cellSize(float reach) const;
  // Exclusive scan of the bound counts; the total to counter `totalSlot` (CSM_COUNTERS: none).
  void scan(uint32_t blocks, uint32_t totalSlot);

  size_t particles_ = 0;
  uint32_t segments_ = 0;
  double meanSegment_ = 0.0;
  double cellPerSegment_ = 0.5;  // cell edge in mean rest segments (cellSize)
  uint32_t buckets_ = 0, scanBlocks_ = 0;
  uint32_t segmentScan_ = 0;           // counts in the per-segment scan (a power of two)
  uint32_t entryCapacity_ = 0;         // grid entries the entry buffer holds
  uint32_t pairListCapacity_ = 0;      // candidate pairs the pair list holds
  uint32_t half_ = 0;                  // which of candidates_ (and of candidateRange_'s halves)
                                       // holds this frame's lists
  uint64_t bufferBytes_ = UINT64_MAX;  // the most one growing buffer may take (limitStorage)
  uint64_t textureTexels_ = 0;         // the most texels one buffer texture holds
  uint64_t viewAlignment_ = 1;         // bytes: where a view of a buffer's range may start
  uint64_t splitTexels_ = UINT64_MAX;  // limitListSplit's cap
  uint32_t listSplit_ = 0;             // texels of the first view of the sides and lists
  bool lastFrameListed_ = false;       // whether the other buffer holds last frame's lists (and
                                       // the counters its measures)
  bool searchPending_ = false;         // searchCounters_ holds a search's, not yet read

  struct Passes {
    ComputePass count, scanBlocks, scanSums, scanAdd, scatter, dispatchSize, candidates, order,
        apply;
    // Without the second view of the sides and the lists, and with it (CSM_SPLIT_VIEWS).
    ComputePass pairScatter[2], lists[2], solve[2];
  } passes_;
  gl::Buffer correction_{gl::NoCreate}, gridCount_{gl::NoCreate}, gridStart_{gl::NoCreate},
      scanBlockSums_{gl::NoCreate}, entries_{gl::NoCreate}, counters_{gl::NoCreate},
      segmentPairs_{gl::NoCreate}, segmentBase_{gl::NoCreate}, segmentScanBlocks_{gl::NoCreate},
      pairList_{gl::NoCreate}, pairSides_{gl::NoCreate}, candidateRange_{gl::NoCreate},
      dispatch_{gl::NoCreate}, searchCounters_{gl::NoCreate}, segmentOrder_{gl::NoCreate};
  gl::Fence searchEnd_;  // after the copy to searchCounters_
  gl::Buffer candidates_[2] = {gl::Buffer(gl::NoCreate), gl::Buffer(gl::NoCreate)};
  // An RG32UI buffer seen as two image views, the second from texel `split` on: more texels
  // than one view holds (CSM_IMAGE_*_HIGH).
  struct SplitView {
    gl::BufferTexture low{gl::NoCreate}, high{gl::NoCreate};
    void attach(const gl::Buffer& buffer, uint64_t texels, uint32_t split);
    void bindImages(GLuint lowUnit, GLuint highUnit, GLenum access) const;
  };
  // Views of the buffers that grow with the hair: texelFetch (entries) and image load / store
  // (CSM_IMAGE_*).
  gl::BufferTexture entryTex_{gl::NoCreate}, gridStartTex_{gl::NoCreate},
      pairListTex_{gl::NoCreate};
  SplitView pairSidesTex_, candidatesTex_[2];
};

}  // namespace csm::gpu
