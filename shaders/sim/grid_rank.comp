// Collision pass, grid build 6b: sorts each bucket by segment index, so the order in which a
// segment meets its contacts (and so its float sums) does not depend on the schedule of the
// scatter's atomics. Each entry's rank is the number of entries of its bucket with a smaller
// segment index: O(bucket size) per entry, all entries in parallel; a bucket holds ~1/27 of
// the candidates the contact pass reads per segment, so this costs a few percent of it.
// Also copies each segment's midpoint next to it, so the contact pass reads candidates
// contiguously.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(std430, binding = CSM_BIND_SEGMENT_DATA) readonly buffer SegmentData { vec4 segData[]; };
layout(std430, binding = CSM_BIND_SEGMENT_BUCKET) readonly buffer SegmentBucket {
  uint segBucket[];
};
layout(std430, binding = CSM_BIND_GRID_START) readonly buffer GridStart { uint gridStart[]; };
layout(std430, binding = CSM_BIND_UNSORTED) readonly buffer Unsorted { uint unsorted[]; };
layout(std430, binding = CSM_BIND_SORTED_DATA) writeonly buffer SortedData { vec4 sortedData[]; };

void main() {
  uint e = globalIndex();
  if (e >= P.counts.z) return;
  uint seg = unsorted[e];
  uint bucket = segBucket[seg];
  uint lo = gridStart[bucket], hi = gridStart[bucket + 1u];
  uint rank = 0u;
  for (uint q = lo; q < hi; ++q) rank += unsorted[q] < seg ? 1u : 0u;
  // w: the segment index, so the contact pass needs one load per candidate (the half length
  // it replaces is bounded by the longest segment's instead).
  sortedData[lo + rank] = vec4(segData[seg].xyz, encodeIndex(seg));
}
