// Strand contacts on the GPU, the search (sim/solver/contacts.h is the CPU reference).
// Once per frame, the candidates: a hash grid of segment boxes built by counting sort
// (grid_count, a three-level parallel scan of the buckets, grid_scatter); candidates.comp per
// grid entry lists the pairs, each once; a counting sort by segment (the same scan over each
// segment's pair count, pair_scatter) and candidate_lists.comp per segment give every segment
// its sorted list. The passes over entries and pairs are dispatched indirectly, sized on the
// GPU by what the frame has (dispatch_size.comp): a generous capacity costs memory, not time. The
// substeps' solve is ContactSolve's (sim/gpu/contact_solve.h); how large the buffers may grow is
// ContactCapacity's (sim/gpu/contact_capacity.h); tests read the lists back through
// sim/gpu/contact_readback.h. The grid's and the pair list's capacities are sized at reset for a
// search of the hair as it stands (sizeForLastSearch), then follow what the last search needed: its
// counters are copied behind a fence as it ends and read as the next one begins (beginFrame), so
// the buffers grow at the same search whatever the GPU's timing and whoever reads the samples (the
// simulation stays deterministic). A search over either capacity keeps each segment's list from
// the search before (its pairs, evaluated where the hair is now; none after a reset or a growth
// of the pair list) and says so in the counters (entries or pairs needed > capacity), and the
// running count of such searches (CSM_COUNTER_OVERFLOWS, ContactStats::overflows) reaches the
// metrics and the panel.
#pragma once

#include <algorithm>
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
#include "sim/gpu/contact_capacity.h"
#include "sim/gpu/contact_solve.h"
#include "sim/gpu/gpu_params.h"
#include "sim/gpu/split_view.h"
#include "sim/gpu/stage_timer.h"
#include "sim/core/results.h"

namespace csm::gpu {

// The contact measures in a counters buffer (CSM_COUNTER_*).
ContactStats contactStatsOf(const uint32_t* counters);

class ContactSearch {
 public:
  // Builds the passes; the lists' second view starts where `solve`'s does too.
  // `device`: defines every pass is built with too (GpuSolver's reads: CSM_STORAGE_READS).
  bool build(std::string* error, ContactSolve& solve, const std::vector<gl::Define>& device = {});
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
  // The strands a search takes: 1 in `stride` by inMeasureSample (a search for the contact
  // measures alone, sim/core/measure_sample.h), or every strand (1: strand contacts). Set
  // before reserveFor; a change forgets the last list (the caller measures anew).
  void setMeasureStride(uint32_t stride) { measureStride_ = std::max<uint32_t>(1, stride); }
  uint32_t measureStride() const { return measureStride_; }
  // Whether reserveFor sized the buffers since the reset (a scene that lists no candidates
  // never allocates them).
  bool reserved() const { return capacity_.entries() > 0; }
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
  // Grows the entry buffer or the pair list when `counters` (read back) say they did not fit;
  // true if either grew. beginFrame calls it with the last search's counters; a tool that reads
  // them at once may too (GpuProbe::detectContacts).
  bool countersSeen(const uint32_t* counters);

  const gl::Buffer& counters() const { return counters_; }
  // The indirect dispatch sizes (CSM_DISPATCH_*), bound at CSM_BIND_DISPATCH with the grid;
  // the volume's node pass keeps its own slot there.
  const gl::Buffer& dispatch() const { return dispatch_; }
  uint32_t entryCapacity() const { return capacity_.entries(); }
  uint32_t pairListCapacity() const { return capacity_.pairs(); }
  // Whether the lists run past their first view (ContactSolve::run needs to know).
  bool splitViews() const { return capacity_.splitViews(); }
  // Caps the buffers that grow with the hair's density (the entries, the pair list, its sides
  // and the lists) at `bytes` each, as a device whose buffer textures hold no more; tests use
  // it to reach the cap with a small scene. A frame that needs more than the capped buffers
  // hold keeps the last list and says so, as any frame over them. Set before reset, it caps
  // what the reset sizes; raised later (UINT64_MAX: the device's own limit), the buffers grow
  // as the next frame begins, as after any overflow. (The storage buffers sized by the
  // particles stay under 128 MiB up to ~4 M particles.)
  void limitStorage(uint64_t bytes) { capacity_.limitStorage(bytes); }
  // collision.contact_memory_mb, in bytes (ContactCapacity::setBudget).
  void setMemoryBudget(uint64_t bytes) { capacity_.setBudget(bytes); }
  // The bytes of its buffers: the grid, the pairs, the candidate lists (both halves).
  uint64_t bytes() const;
  // Caps the texels of the first view of the sides and of the lists at `texels` (as on a
  // device whose buffer textures hold no more), before reset; tests use it to put a small
  // scene's lists across both views.
  void limitListSplit(uint64_t texels);
  uint32_t listSplit() const { return capacity_.listSplit(); }
  uint32_t bucketCount() const { return buckets_; }

  // What the read-backs (sim/gpu/contact_readback.h) read.
  size_t particles() const { return particles_; }
  uint32_t half() const { return half_; }
  const gl::Buffer& pairList() const { return pairList_; }
  const gl::Buffer& candidateRange() const { return candidateRange_; }
  const gl::Buffer& candidates(uint32_t half) const { return candidates_[half]; }
  const gl::Buffer& segmentOrder() const { return segmentOrder_; }

 private:
  // The buffers made again when the capacity grows for `needed` items.
  void growEntries(uint64_t needed);
  void growPairList(uint64_t needed);
  // The last search's counters, copied when it ended: grows the buffers to what it needed.
  void growFromLastSearch();
  // The passes' uniform for where the lists' second view starts; true.
  bool setListSplit();
  // Both builds of a pass that reads or writes the sides or the lists.
  bool buildSplit(ComputePass (&pass)[2], const char* path, std::string* error);
  // `defines` and the device's.
  std::vector<gl::Define> with(std::vector<gl::Define> defines) const;
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
  uint32_t segmentScan_ = 0;       // counts in the per-segment scan (a power of two)
  uint32_t measureStride_ = 1;     // the strands searched: 1 in this many (inMeasureSample)
  ContactCapacity capacity_;       // the entries and pairs the buffers hold, and may
  ContactSolve* solve_ = nullptr;  // told where the lists' second view starts
  uint32_t half_ = 0;              // which of candidates_ (and of candidateRange_'s halves)
                                   // holds this frame's lists
  bool lastFrameListed_ = false;   // whether the other buffer holds last frame's lists (and
                                   // the counters its measures)
  bool searchPending_ = false;     // searchCounters_ holds a search's, not yet read

  struct Passes {
    ComputePass count, scanBlocks, scanSums, scanAdd, scatter, dispatchSize, candidates, order;
    // Without the second view of the sides and the lists, and with it (CSM_SPLIT_VIEWS).
    ComputePass pairScatter[2], lists[2];
  } passes_;
  gl::Buffer gridCount_{gl::NoCreate}, gridStart_{gl::NoCreate}, scanBlockSums_{gl::NoCreate},
      entries_{gl::NoCreate}, counters_{gl::NoCreate}, segmentPairs_{gl::NoCreate},
      segmentBase_{gl::NoCreate}, segmentScanBlocks_{gl::NoCreate}, pairList_{gl::NoCreate},
      pairSides_{gl::NoCreate}, candidateRange_{gl::NoCreate}, dispatch_{gl::NoCreate},
      searchCounters_{gl::NoCreate}, segmentOrder_{gl::NoCreate};
  std::vector<gl::Define> device_;  // added to every pass's defines
  gl::Fence searchEnd_;             // after the copy to searchCounters_
  gl::Buffer candidates_[2] = {gl::Buffer(gl::NoCreate), gl::Buffer(gl::NoCreate)};
  // Views of the buffers that grow with the hair: texelFetch (entries) and image load / store
  // (CSM_IMAGE_*).
  gl::BufferTexture entryTex_{gl::NoCreate}, gridStartTex_{gl::NoCreate},
      pairListTex_{gl::NoCreate};
  SplitView pairSidesTex_, candidatesTex_[2];
};

}  // namespace csm::gpu
