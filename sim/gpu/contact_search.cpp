#include "sim/gpu/contact_search.h"

#include <algorithm>
#include <bit>
#include <numeric>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "gl/caps.h"
#include "sim/core/measure_sample.h"
#include "sim/gpu/buffer_fill.h"
#include "shaders/sim/bindings.glsl"

namespace csm::gpu {
namespace {

// The counters a search copies for the next one's growth: up to the pairs it needed.
constexpr uint32_t kSearchCounters = CSM_COUNTER_PAIR_LIST + 1;
static_assert(CSM_COUNTER_ENTRIES < kSearchCounters);

// Boxes are padded by half the candidate distance (2r + margin) and 1%, so that a pair the
// candidate pass finds closer than that in float always has overlapping boxes.
constexpr float kPadSlack = 1.01f;
// Cells are at least this many mean rest segments long: half in dense hair, three quarters
// where a sizing search found at most kSparsePairs candidate pairs a segment (cellSize says
// why).
constexpr double kDenseCellPerSegment = 0.5, kSparseCellPerSegment = 0.75;
constexpr uint64_t kSparsePairs = 20;
// A segment enters at most CSM_MAX_SEGMENT_CELLS cells (4 x 4 x 4): a box of a strain-limited
// segment spans at most 4 cells per axis (cells are at least half a mean segment), so only a
// segment stretched to ~1.5 mean lengths or more misses it. Such a segment is in no cell this
// frame (counted as oversize), which keeps the pass bounded when a simulation explodes.
constexpr uint32_t kMaxSegmentCells = CSM_MAX_SEGMENT_CELLS;

}  // namespace

bool ContactSearch::build(std::string* error, ContactSolve& solve,
                          const std::vector<gl::Define>& device) {
  solve_ = &solve;
  device_ = device;
  // What one buffer texture may hold here (llvmpipe and NVIDIA: 2^27 texels; GL 4.3 guarantees
  // 2^16): the buffers that grow with the hair are read and written through such views (a
  // view past it is read and written as the implementation pleases).
  const gl::Caps caps = gl::queryCaps();
  capacity_.setDevice(uint64_t(std::max<GLint>(caps.maxTextureBufferSize, 0)),
                      uint64_t(std::max<GLint>(caps.textureBufferOffsetAlignment, 1)));
  searchCounters_ = gl::Buffer();
  searchCounters_.setData(kSearchCounters * sizeof(uint32_t), nullptr, gl::BufferUsage::StreamRead);
  return passes_.count.build("sim/grid_count.comp", CSM_PARTICLE_GROUP, with({}), error) &&
         passes_.scanBlocks.build("sim/scan_blocks.comp", CSM_PARTICLE_GROUP, with({}), error) &&
         passes_.scanSums.build("sim/scan_sums.comp", CSM_SCAN_GROUP, with({}), error) &&
         passes_.scanAdd.build("sim/scan_add.comp", CSM_PARTICLE_GROUP, with({}), error) &&
         passes_.scatter.build("sim/grid_scatter.comp", CSM_PARTICLE_GROUP, with({}), error) &&
         passes_.dispatchSize.build("sim/dispatch_size.comp", 1, with({}), error) &&
         passes_.candidates.build("sim/candidates.comp", CSM_CONTACT_GROUP, with({}), error) &&
         passes_.order.build("sim/segment_order.comp", CSM_PARTICLE_GROUP, with({}), error) &&
         buildSplit(passes_.pairScatter, "sim/pair_scatter.comp", error) &&
         buildSplit(passes_.lists, "sim/candidate_lists.comp", error) &&
         solve.build(error, device) && setListSplit();
}

bool ContactSearch::buildSplit(ComputePass (&pass)[2], const char* path, std::string* error) {
  return pass[0].build(path, CSM_PARTICLE_GROUP, with({}), error) &&
         pass[1].build(path, CSM_PARTICLE_GROUP, with({{"CSM_SPLIT_VIEWS", ""}}), error);
}

std::vector<gl::Define> ContactSearch::with(std::vector<gl::Define> defines) const {
  defines.insert(defines.end(), device_.begin(), device_.end());
  return defines;
}

bool ContactSearch::setListSplit() {
  // The second view of the sides and of the lists starts where the first ends.
  const uint32_t split = capacity_.listSplit();
  for (ComputePass* pass : {&passes_.pairScatter[1], &passes_.lists[1]})
    pass->set("listSplit", split);
  if (solve_) solve_->setListSplit(split);
  return true;
}

void ContactSearch::limitListSplit(uint64_t texels) {
  capacity_.limitListSplit(texels);
  setListSplit();
}

void ContactSearch::reset(size_t particles, uint32_t segments, double meanSegment) {
  particles_ = particles;
  segments_ = segments;
  meanSegment_ = meanSegment;
  // Two buckets per segment (a power of two, so the hash is masked): dense hair fills far
  // fewer cells than that, sparse hair about as many, so few buckets hold two cells.
  buckets_ = std::max<uint32_t>(64, std::bit_ceil(std::max<uint32_t>(2 * segments, 1)));
  scanBlocks_ = buckets_ / CSM_SCAN_LEAF;
  // The per-segment scan (where each segment's pairs start) runs on the same scan passes, over
  // one count per particle.
  segmentScan_ = std::max<uint32_t>(64, std::bit_ceil(uint32_t(particles)));
  zeroed<glm::uvec2>(candidateRange_, 2 * particles);
  half_ = 0;
  lastFrameListed_ = false;
  cellPerSegment_ = kDenseCellPerSegment;  // until a search of the hair says (sizeForLastSearch)
  zeroed<uint32_t>(gridCount_, buckets_);
  zeroed<uint32_t>(gridStart_, buckets_ + 4);  // + the total, as a uvec4
  zeroed<uint32_t>(scanBlockSums_, scanBlocks_ + 1);
  zeroed<uint32_t>(counters_, CSM_COUNTERS);
  zeroed<glm::uvec4>(dispatch_, CSM_DISPATCHES);
  zeroed<uint32_t>(segmentPairs_, segmentScan_);
  zeroed<uint32_t>(segmentBase_, segmentScan_ + 4);
  zeroed<uint32_t>(segmentScanBlocks_, segmentScan_ / CSM_SCAN_LEAF + 1);
  std::vector<uint32_t> order(particles);  // in index order until the first search
  std::iota(order.begin(), order.end(), 0u);
  fill(segmentOrder_, order);
  view(gridStartTex_, gridStart_, gl::TextureFormat::R32ui);
  searchPending_ = false;
  capacity_.clear();  // reserveFor sizes the entry buffer and the pair list
}

double ContactSearch::cellSize(float reach) const {
  // Cells of at least twice the candidate distance and half or three quarters of a mean rest
  // segment (the CPU reference, findContactsGrid, takes half the current median; the pairs
  // found do not depend on the cell, only the search's cost does). Larger cells hold fewer
  // entries to count and scatter (Fig. 1: 3.4 a segment instead of 5.0) and more candidates
  // to test in each: on llvmpipe three quarters made the search 6-14 % cheaper at 3,000 to
  // 23,000 strands of the paper's scenes (4.6-7.3 pairs a segment), the same at 30,000 of
  // Fig. 1 (22) and 23 % dearer at 100,000 (75); docs/BENCHMARKS_HISTORY.md.
  return std::max({2.0 * double(reach), cellPerSegment_ * meanSegment_, 1e-6});
}

void ContactSearch::reserveFor(std::span<const glm::vec4> x, std::span<const uint32_t> strand,
                               float reach, const glm::vec3& origin) {
  const double cell = cellSize(reach), pad = 0.5 * reach * kPadSlack;
  uint64_t entries = 0;
  for (size_t i = 0; i + 1 < x.size(); ++i) {
    if (strand[i] != strand[i + 1] || !inMeasureSample(strand[i], measureStride_)) continue;
    const glm::dvec3 p0 = glm::dvec3(glm::vec3(x[i]) - origin);
    const glm::dvec3 p1 = glm::dvec3(glm::vec3(x[i + 1]) - origin);
    const glm::dvec3 lo = glm::floor((glm::min(p0, p1) - pad) / cell);
    const glm::dvec3 hi = glm::floor((glm::max(p0, p1) + pad) / cell);
    const glm::dvec3 span = hi - lo + 1.0;
    entries += std::min<uint64_t>(kMaxSegmentCells, uint64_t(span.x * span.y * span.z));
  }
  growEntries(std::max<uint64_t>(1, entries + entries / 2));
  // Dense hair has about as many candidate pairs as entries at rest, but hair that settles
  // onto itself and that the wind gathers has more: Fig. 1 on the mannequin goes from 1.0 to
  // 4.0 pairs per estimated entry in its first 12 frames (cells of half a segment), and with
  // twice the entries reserved two of its frames had no strand contacts before the list grew.
  // Four times as many, and a quarter more (growPairList); the growth after an overflow stays
  // for what this misses (such a frame keeps the lists before it). The reset's cells are half
  // a segment (dense), as when this was measured; the reset's own search sizes the list too
  // (sizeForLastSearch).
  growPairList(std::max<uint64_t>(1024, 4 * entries));
}

void ContactSearch::beginFrame(bool contacts) {
  growFromLastSearch();
  if (contacts && !lastFrameListed_) {
    // No last list: nothing to count crossings against.
    candidateRange_.clearToZero();
  } else if (!contacts && lastFrameListed_) {
    // Nothing to report this frame.
    clearFrameCounters();
  }
  half_ ^= 1u;
  lastFrameListed_ = contacts;
}

void ContactSearch::writeParams(SimParams& p, float reach) const {
  p.bucketMask = buckets_ - 1;
  p.entryCapacity = capacity_.entries();
  p.pairListCapacity = capacity_.pairs();
  p.listHalf = half_;
  const double cell = cellSize(reach);
  p.cellEdge = float(cell);
  p.inverseCellEdge = float(1.0 / cell);
  p.cellPadding = 0.5f * reach * kPadSlack + 1e-7f;
}

void ContactSearch::bind() const {
  const gl::BufferTarget ssbo = gl::BufferTarget::ShaderStorage;
  gridCount_.bindBase(ssbo, CSM_BIND_GRID_COUNT);
  gridStart_.bindBase(ssbo, CSM_BIND_GRID_START);
  scanBlockSums_.bindBase(ssbo, CSM_BIND_SCAN_BLOCKS);
  counters_.bindBase(ssbo, CSM_BIND_COUNTERS);
  dispatch_.bindBase(ssbo, CSM_BIND_DISPATCH);
  segmentPairs_.bindBase(ssbo, CSM_BIND_SEGMENT_PAIRS);
  segmentBase_.bindBase(ssbo, CSM_BIND_SEGMENT_BASE);
  segmentOrder_.bindBase(ssbo, CSM_BIND_SEGMENT_ORDER);
  candidateRange_.bindBase(ssbo, CSM_BIND_CANDIDATE_RANGE);
  entryTex_.bind(CSM_TEX_ENTRIES);
  gridStartTex_.bind(CSM_TEX_GRID_START);
  entryTex_.bindImage(CSM_IMAGE_ENTRIES, gl::ImageAccess::WriteOnly, gl::TextureFormat::Rgba32ui);
  pairListTex_.bindImage(CSM_IMAGE_PAIR_LIST, gl::ImageAccess::ReadWrite,
                         gl::TextureFormat::Rgba32ui);
  pairSidesTex_.bindImages(CSM_IMAGE_PAIR_SIDES, CSM_IMAGE_PAIR_SIDES_HIGH,
                           gl::ImageAccess::ReadWrite);
  candidatesTex_[half_].bindImages(CSM_IMAGE_CANDIDATES, CSM_IMAGE_CANDIDATES_HIGH,
                                   gl::ImageAccess::ReadWrite);
  candidatesTex_[half_ ^ 1u].bindImages(CSM_IMAGE_LAST_CANDIDATES, CSM_IMAGE_LAST_CANDIDATES_HIGH,
                                        gl::ImageAccess::ReadOnly);
}

void ContactSearch::findCandidates(StageTimer* timer, bool measured) {
  if (segments_ == 0) return;
  const uint32_t particles = uint32_t(particles_);
  if (timer) timer->stage(kGrid);
  if (measured) {
    clearFrameCounters();
  } else {
    // Only the pair list's append counter (the entries' total is written by their scan); the
    // measures stay the frame's first list's.
    counters_.clearToZero(CSM_COUNTER_PAIR_LIST * sizeof(uint32_t), sizeof(uint32_t));
  }
  passes_.candidates.set("measured", measured ? 1u : 0u);
  passes_.count.set("measureStride", measureStride_).run(particles);
  gl::memoryBarrier(kPassBarrier);
  // Counting sort of the entries by bucket: exclusive scan of the counts, scatter.
  scan(scanBlocks_, CSM_COUNTER_ENTRIES);
  passes_.scatter.set("measureStride", measureStride_).run(particles);
  gl::memoryBarrier(kPassBarrier);
  // One invocation per entry: how many there are is known on the GPU only (no read-back inside
  // a frame), so the dispatch is sized there.
  dispatchFor(CSM_COUNTER_ENTRIES, capacity_.entries(), CSM_CONTACT_GROUP, CSM_DISPATCH_CANDIDATES);
  passes_.candidates.runIndirect(dispatch_, CSM_DISPATCH_CANDIDATES);
  gl::memoryBarrier(kPassBarrier);
  // Counting sort of the pairs by segment: the same scan over the segments' pair counts, its
  // buffers bound in the grid's place for the while; scatter, one invocation per listed
  // pair.
  const gl::BufferTarget ssbo = gl::BufferTarget::ShaderStorage;
  segmentPairs_.bindBase(ssbo, CSM_BIND_GRID_COUNT);
  segmentBase_.bindBase(ssbo, CSM_BIND_GRID_START);
  segmentScanBlocks_.bindBase(ssbo, CSM_BIND_SCAN_BLOCKS);
  scan(segmentScan_ / CSM_SCAN_LEAF, CSM_COUNTERS);
  gridCount_.bindBase(ssbo, CSM_BIND_GRID_COUNT);
  gridStart_.bindBase(ssbo, CSM_BIND_GRID_START);
  scanBlockSums_.bindBase(ssbo, CSM_BIND_SCAN_BLOCKS);
  // The segments by candidate count, for the list pass and the substeps' contact solves.
  passes_.order.run(particles);
  gl::memoryBarrier(kPassBarrier);
  dispatchFor(CSM_COUNTER_PAIR_LIST, capacity_.pairs(), CSM_PARTICLE_GROUP,
              CSM_DISPATCH_PAIR_SCATTER);
  passes_.pairScatter[capacity_.splitViews()].runIndirect(dispatch_, CSM_DISPATCH_PAIR_SCATTER);
  gl::memoryBarrier(kPassBarrier);
  passes_.lists[capacity_.splitViews()].run(particles);
  gl::memoryBarrier(kPassBarrier);
  // What this search needed, for the next one's beginFrame.
  gl::memoryBarrier(gl::Barrier::BufferUpdate);
  counters_.copyTo(searchCounters_, 0, 0, kSearchCounters * sizeof(uint32_t));
  searchEnd_ = gl::Fence::insert();
  searchPending_ = true;
}

void ContactSearch::sizeForLastSearch() {
  if (segments_ == 0) return;
  searchPending_ = false;  // read here instead
  const std::vector<uint32_t> c = counters_.download<uint32_t>(CSM_COUNTERS);
  // The cells for the hair as it stands: three quarters of a segment where it has few pairs
  // a segment (a search whose grid did not fit counts no pairs: kept dense). Cells half as
  // long hold ~1.5x the entries (Fig. 1): twice what this search needed, then.
  const double searched = cellPerSegment_;
  const bool sparse = c[CSM_COUNTER_ENTRIES] <= capacity_.entries() &&
                      uint64_t(c[CSM_COUNTER_PAIR_LIST]) <= kSparsePairs * segments_;
  cellPerSegment_ = sparse ? kSparseCellPerSegment : kDenseCellPerSegment;
  // A quarter over what it needed, as after an overflow: growEntries and growPairList keep
  // what is there when that holds it.
  growEntries(uint64_t(c[CSM_COUNTER_ENTRIES]) * (cellPerSegment_ < searched ? 2 : 1));
  growPairList(c[CSM_COUNTER_PAIR_LIST]);
  // Forgotten: the first frame counts no crossings against it, and no frame over capacity.
  counters_.clearToZero();
  candidateRange_.clearToZero();
  lastFrameListed_ = false;
}

void ContactSearch::growFromLastSearch() {
  if (!searchPending_) return;
  searchPending_ = false;
  searchEnd_.wait();
  uint32_t c[kSearchCounters];
  searchCounters_.read(0, sizeof c, c);
  countersSeen(c);
}

void ContactSearch::dispatchFor(uint32_t counter, uint32_t capacity, uint32_t groupSize,
                                uint32_t slot) {
  passes_.dispatchSize.set("counter", counter)
      .set("capacity", capacity)
      .set("groupSize", groupSize)
      .set("slot", slot)
      .run(1);
  gl::memoryBarrier(gl::Barrier::Command);
}

void ContactSearch::clearFrameCounters() {
  counters_.clearToZero(0, CSM_COUNTERS_PER_FRAME * sizeof(uint32_t));
}

void ContactSearch::scan(uint32_t blocks, uint32_t totalSlot) {
  // Block sums, their scan, each block rescanned from its offset (scan_*.comp).
  passes_.scanBlocks.set("blocks", blocks).run(blocks);
  gl::memoryBarrier(kPassBarrier);
  passes_.scanSums.set("count", blocks).run(1);
  gl::memoryBarrier(kPassBarrier);
  passes_.scanAdd.set("blocks", blocks).set("totalSlot", totalSlot).run(blocks);
  gl::memoryBarrier(kPassBarrier);
}

bool ContactSearch::countersSeen(const uint32_t* c) {
  // The grid or the pair list did not fit that frame (it kept the lists before it): room for
  // the next.
  bool grew = false;
  if (c[CSM_COUNTER_ENTRIES] > capacity_.entries()) {
    growEntries(c[CSM_COUNTER_ENTRIES]);
    grew = true;
  }
  if (c[CSM_COUNTER_PAIR_LIST] > capacity_.pairs()) {
    growPairList(c[CSM_COUNTER_PAIR_LIST]);
    grew = true;
  }
  return grew;
}

void ContactSearch::growEntries(uint64_t needed) {
  if (!capacity_.growEntries(needed)) return;
  zeroed<glm::uvec4>(entries_, capacity_.entries());
  view(entryTex_, entries_, gl::TextureFormat::Rgba32ui);
}

void ContactSearch::growPairList(uint64_t needed) {
  if (!capacity_.growPairs(needed)) return;
  zeroed<glm::uvec4>(pairList_, capacity_.pairs());
  view(pairListTex_, pairList_, gl::TextureFormat::Rgba32ui);
  const uint64_t sides = 2 * uint64_t(capacity_.pairs());
  const uint32_t split = capacity_.listSplit();
  zeroed<glm::uvec2>(pairSides_, sides);
  pairSidesTex_.attach(pairSides_, sides, split);
  // Both frames' lists, two sides per pair each; last frame's lists are gone, and their
  // ranges with them (a search over the grown list that still does not fit keeps none).
  for (int h = 0; h < 2; ++h) {
    zeroed<glm::uvec2>(candidates_[h], sides);
    candidatesTex_[h].attach(candidates_[h], sides, split);
  }
  candidateRange_.clearToZero();
  lastFrameListed_ = false;
}

ContactStats contactStatsOf(const uint32_t* c) {
  ContactStats s;
  s.candidates = c[CSM_COUNTER_CANDIDATES];
  s.contacts = c[CSM_COUNTER_CONTACTS];
  s.penetrations = c[CSM_COUNTER_PENETRATIONS];
  s.crossings = c[CSM_COUNTER_CROSSINGS];
  s.crossingsClose = c[CSM_COUNTER_CROSSINGS_CLOSE];
  s.overflows = c[CSM_COUNTER_OVERFLOWS];
  s.oversize = c[CSM_COUNTER_OVERSIZE];
  s.crowded = c[CSM_COUNTER_CROWDED];
  s.maxDepth = std::bit_cast<float>(c[CSM_COUNTER_MAX_DEPTH]);
  static_assert(CSM_DEPTH_BINS == kDepthBins && CSM_DEPTH_BINS_PER_R == kDepthBinsPerR);
  for (int i = 0; i < kDepthBins; ++i) s.depth[i] = c[CSM_COUNTER_DEPTH + i];
  return s;
}

uint64_t ContactSearch::bytes() const {
  uint64_t sum = 0;
  for (const gl::Buffer* b :
       {&gridCount_, &gridStart_, &scanBlockSums_, &entries_, &counters_, &segmentPairs_,
        &segmentBase_, &segmentScanBlocks_, &pairList_, &pairSides_, &candidateRange_, &dispatch_,
        &searchCounters_, &segmentOrder_, &candidates_[0], &candidates_[1]})
    sum += uint64_t(b->size());
  return sum;
}

}  // namespace csm::gpu
