// Collision pass, grid build 6b: sorts each bucket by midpoint x, then segment index. The
// order makes the sums deterministic (a segment meets its contacts in a fixed order whatever
// the schedule of the scatter's atomics), and sorting by x lets the contact pass cut the
// x-neighbouring buckets of a run to the reachable window by binary search. Each entry's
// rank is the number of entries of its bucket before it in that order: O(bucket size) per
// entry, all entries in parallel; a bucket holds ~1/27 of the candidates the contact pass
// reads per segment, so this costs a few percent of it.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(binding = CSM_TEX_UNSORTED) uniform samplerBuffer unsortedTex;

layout(std430, binding = CSM_BIND_SEGMENT_BUCKET) readonly buffer SegmentBucket {
  uint segBucket[];
};
layout(std430, binding = CSM_BIND_GRID_START) readonly buffer GridStart { uint gridStart[]; };
layout(std430, binding = CSM_BIND_SORTED_DATA) writeonly buffer SortedData { vec4 sortedData[]; };

void main() {
  uint e = globalIndex();
  if (e >= P.counts.z) return;
  vec4 me = texelFetch(unsortedTex, int(e));
  uint seg = decodeIndex(me.w);
  uint bucket = segBucket[seg];
  uint lo = gridStart[bucket], hi = gridStart[bucket + 1u];
  uint rank = 0u;
  for (uint q = lo; q < hi; ++q) {
    vec4 other = texelFetch(unsortedTex, int(q));
    bool before = other.x < me.x || (other.x == me.x && decodeIndex(other.w) < seg);
    rank += before ? 1u : 0u;
  }
  sortedData[lo + rank] = me;
}
