#include "sim/gpu/collision_grid.h"

#include <algorithm>
#include <bit>

#include "gl/draw.h"
#include "sim/gpu/buffer_fill.h"
#include "shaders/sim/bindings.glsl"

namespace csm::gpu {
namespace {

// Boxes are padded by r (half the contact distance) and 1%, so that a pair the contact pass
// finds closer than 2r in float always has overlapping boxes.
constexpr float kPadSlack = 1.01f;
// A segment enters at most this many cells (4 x 4 x 4): a box of a strain-limited segment
// spans at most 3 cells per axis (cells are at least half a mean segment), so only a segment
// stretched to ~1.5 mean lengths or more misses it. Such a segment is in no cell this frame
// (counted as oversize), which keeps the pass bounded when a simulation explodes.
constexpr uint32_t kMaxSegmentCells = 64;
// Entry buffers start at this many entries per segment (Fig. 1 needs ~7); when a frame needs
// more, the pass skips that frame and the buffers grow (see growEntries).
constexpr uint32_t kEntriesPerSegment = 10;

}  // namespace

bool CollisionGrid::build(std::string* error) {
  return passes_.count.build("sim/grid_count.comp", CSM_PARTICLE_GROUP, {}, error) &&
         passes_.scanBlocks.build("sim/scan_blocks.comp", CSM_PARTICLE_GROUP, {}, error) &&
         passes_.scanSums.build("sim/scan_sums.comp", CSM_SCAN_GROUP, {}, error) &&
         passes_.scanAdd.build("sim/scan_add.comp", CSM_PARTICLE_GROUP, {}, error) &&
         passes_.scatter.build("sim/grid_scatter.comp", CSM_PARTICLE_GROUP, {}, error) &&
         passes_.contacts.build("sim/contacts.comp", CSM_CONTACT_GROUP, {}, error) &&
         passes_.segmentForces.build("sim/segment_forces.comp", CSM_PARTICLE_GROUP, {}, error);
}

void CollisionGrid::reset(size_t particles, uint32_t segments, double meanSegment) {
  particles_ = particles;
  segments_ = segments;
  meanSegment_ = meanSegment;
  // Two buckets per segment (a power of two, so the hash is masked): dense hair fills far
  // fewer cells than that, sparse hair about as many, so few buckets hold two cells.
  buckets_ = std::max<uint32_t>(64, std::bit_ceil(std::max<uint32_t>(2 * segments, 1)));
  scanBlocks_ = buckets_ / CSM_SCAN_LEAF;
  // The per-segment scan (where each segment's partial forces start) runs on the same scan
  // passes, over one count per particle.
  segmentScan_ = std::max<uint32_t>(64, std::bit_ceil(uint32_t(particles)));
  zeroed<glm::vec4>(segmentForce_, 2 * particles);
  zeroed<uint32_t>(gridCount_, buckets_);
  zeroed<uint32_t>(gridStart_, buckets_ + 4);  // + the total, as a uvec4
  zeroed<uint32_t>(scanBlockSums_, scanBlocks_ + 1);
  zeroed<uint32_t>(counters_, CSM_COUNTERS);
  zeroed<uint32_t>(segmentCells_, segmentScan_);
  zeroed<uint32_t>(segmentBase_, segmentScan_ + 4);
  zeroed<uint32_t>(segmentScanBlocks_, segmentScan_ / CSM_SCAN_LEAF + 1);
  zeroed<glm::uvec2>(pairs_, pairCapacity_);
  zeroed<uint32_t>(segmentContacts_, particles);
  view(gridStartTex_, gridStart_, GL_R32UI);
  entryCapacity_ = 0;
  growEntries(std::max<uint64_t>(1, uint64_t(segments) * kEntriesPerSegment));
}

void CollisionGrid::writeParams(SimParams& p, float radius) const {
  p.counts.w = uint32_t(pairCapacity_);
  p.grid = glm::uvec4(buckets_ - 1, entryCapacity_, kMaxSegmentCells, 0);
  // Cells of at least twice the contact distance and half a mean segment, as the CPU
  // reference (findContactsGrid): a segment then enters ~2-12 cells, and a cell holds about a
  // sixteenth of what a cell as long as a segment holds.
  const double cell = std::max({4.0 * double(radius), 0.5 * meanSegment_, 1e-6});
  p.cells = glm::vec4(float(cell), float(1.0 / cell), radius * kPadSlack + 1e-7f, 0.0f);
}

void CollisionGrid::bind() const {
  const GLenum ssbo = GL_SHADER_STORAGE_BUFFER;
  segmentForce_.bindBase(ssbo, CSM_BIND_SEGMENT_FORCE);
  gridCount_.bindBase(ssbo, CSM_BIND_GRID_COUNT);
  gridStart_.bindBase(ssbo, CSM_BIND_GRID_START);
  scanBlockSums_.bindBase(ssbo, CSM_BIND_SCAN_BLOCKS);
  entryHigh_.bindBase(ssbo, CSM_BIND_ENTRY_HIGH);
  entryLow_.bindBase(ssbo, CSM_BIND_ENTRY_LOW);
  counters_.bindBase(ssbo, CSM_BIND_COUNTERS);
  pairs_.bindBase(ssbo, CSM_BIND_PAIRS);
  segmentContacts_.bindBase(ssbo, CSM_BIND_SEGMENT_CONTACTS);
  segmentCells_.bindBase(ssbo, CSM_BIND_SEGMENT_CELLS);
  segmentBase_.bindBase(ssbo, CSM_BIND_SEGMENT_BASE);
  partialForce_.bindBase(ssbo, CSM_BIND_PARTIAL_FORCE);
  entryLowTex_.bind(CSM_TEX_ENTRY_LOW);
  gridStartTex_.bind(CSM_TEX_GRID_START);
  entryHighTex_.bind(CSM_TEX_ENTRY_HIGH);
}

void CollisionGrid::run(StageTimer& timer) {
  if (segments_ == 0) return;
  const uint32_t particles = uint32_t(particles_);
  timer.stage(kGrid);
  counters_.clearToZero();
  passes_.count.run(particles);
  gl::memoryBarrier(kPassBarrier);
  // Counting sort, exclusive scan of the bucket counts; then the same scan over the
  // segments' cell counts, its buffers bound in the grid's place for the while.
  scan(scanBlocks_);
  const GLenum ssbo = GL_SHADER_STORAGE_BUFFER;
  segmentCells_.bindBase(ssbo, CSM_BIND_GRID_COUNT);
  segmentBase_.bindBase(ssbo, CSM_BIND_GRID_START);
  segmentScanBlocks_.bindBase(ssbo, CSM_BIND_SCAN_BLOCKS);
  scan(segmentScan_ / CSM_SCAN_LEAF);
  gridCount_.bindBase(ssbo, CSM_BIND_GRID_COUNT);
  gridStart_.bindBase(ssbo, CSM_BIND_GRID_START);
  scanBlockSums_.bindBase(ssbo, CSM_BIND_SCAN_BLOCKS);
  passes_.scatter.run(particles);
  gl::memoryBarrier(kPassBarrier);
  timer.stage(kContacts);
  // One invocation per entry slot: how many are used is known on the GPU only (no read-back
  // inside a frame); the others return at once.
  passes_.contacts.run(entryCapacity_);
  gl::memoryBarrier(kPassBarrier);
  passes_.segmentForces.run(particles);
  gl::memoryBarrier(kPassBarrier);
}

void CollisionGrid::scan(uint32_t blocks) {
  // Block sums, their scan, each block rescanned from its offset (scan_*.comp).
  passes_.scanBlocks.set("blocks", blocks).run(blocks);
  gl::memoryBarrier(kPassBarrier);
  passes_.scanSums.set("count", blocks).run(1);
  gl::memoryBarrier(kPassBarrier);
  passes_.scanAdd.set("blocks", blocks).run(blocks);
  gl::memoryBarrier(kPassBarrier);
}

bool CollisionGrid::countersSeen(const uint32_t* c) {
  // The grid did not fit that frame (it applied no hair-hair forces): room for the next.
  if (c[CSM_COUNTER_ENTRIES] <= entryCapacity_) return false;
  growEntries(c[CSM_COUNTER_ENTRIES]);
  return true;
}

void CollisionGrid::growEntries(uint64_t needed) {
  // A quarter more than asked, so a growing tangle does not reallocate every frame; never
  // beyond what a 32-bit index and one buffer can hold.
  const uint64_t limit = uint64_t(1) << 27;  // 2 GiB of 16-byte entries
  const uint64_t want = std::min(limit, needed + needed / 4);
  if (want <= entryCapacity_) return;
  entryCapacity_ = uint32_t(want);
  zeroed<glm::uvec4>(entryLow_, entryCapacity_);
  zeroed<glm::uvec4>(entryHigh_, entryCapacity_);
  zeroed<glm::vec4>(partialForce_, 2 * size_t(entryCapacity_));
  view(entryLowTex_, entryLow_, GL_RGBA32UI);
  view(entryHighTex_, entryHigh_, GL_RGBA32UI);
}

std::vector<uint32_t> CollisionGrid::readCounters() const {
  return counters_.download<uint32_t>(CSM_COUNTERS);
}

void CollisionGrid::setPairCapacity(size_t capacity) {
  pairCapacity_ = capacity;
  zeroed<glm::uvec2>(pairs_, pairCapacity_);
}

std::vector<std::pair<uint32_t, uint32_t>> CollisionGrid::readPairs(bool* overflow) const {
  const std::vector<uint32_t> c = readCounters();
  const size_t found = c[CSM_COUNTER_PAIRS];
  if (overflow) *overflow = found > pairCapacity_;
  const size_t n = std::min(found, pairCapacity_);
  std::vector<std::pair<uint32_t, uint32_t>> out;
  out.reserve(n);
  for (const glm::uvec2& p : pairs_.download<glm::uvec2>(n)) out.emplace_back(p.x, p.y);
  return out;
}

std::vector<uint32_t> CollisionGrid::readSegmentContactCounts() const {
  return segmentContacts_.download<uint32_t>(particles_);
}

}  // namespace csm::gpu
