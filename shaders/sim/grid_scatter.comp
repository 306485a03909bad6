// Collision pass, grid build 6a (counting sort: scatter): each segment takes a slot in its
// bucket's range, with its midpoint. Counting the bucket back down returns the counts to zero for the next
// frame (no clear needed); the order within a bucket depends on the schedule, which the
// rank pass (grid_rank.comp) then removes.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_SEGMENT_BUCKET) readonly buffer SegmentBucket {
  uint segBucket[];
};
layout(std430, binding = CSM_BIND_GRID_COUNT) buffer GridCount { uint gridCount[]; };
layout(std430, binding = CSM_BIND_GRID_START) readonly buffer GridStart { uint gridStart[]; };
layout(std430, binding = CSM_BIND_SEGMENT_DATA) readonly buffer SegmentData { vec4 segData[]; };
layout(std430, binding = CSM_BIND_UNSORTED) writeonly buffer Unsorted { vec4 unsorted[]; };

void main() {
  uint i = globalIndex();
  if (i + 1u >= P.counts.x || particleStrand[i] != particleStrand[i + 1u]) return;
  uint bucket = segBucket[i];
  uint slot = gridStart[bucket] + atomicAdd(gridCount[bucket], 0xffffffffu) - 1u;
  unsorted[slot] = vec4(segData[i].xyz, encodeIndex(i));
}
