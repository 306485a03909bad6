// Collision pass, grid build 2/6 (counting sort: count): each segment finds its cell's
// bucket and counts itself in. Integer atomics: the counts do not depend on the order.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_SEGMENT_DATA) readonly buffer SegmentData { vec4 segData[]; };
layout(std430, binding = CSM_BIND_SEGMENT_BUCKET) writeonly buffer SegmentBucket {
  uint segBucket[];
};
layout(std430, binding = CSM_BIND_GRID_COUNT) buffer GridCount { uint gridCount[]; };
layout(std430, binding = CSM_BIND_COUNTERS) readonly buffer Counters { uint counters[]; };

void main() {
  uint i = globalIndex();
  if (i + 1u >= P.counts.x || particleStrand[i] != particleStrand[i + 1u]) return;
  float cell = cellSize(counters[CSM_COUNTER_LONGEST]);
  uint bucket = bucketOf(cellOf(segData[i].xyz, cell));
  segBucket[i] = bucket;
  atomicAdd(gridCount[bucket], 1u);
}
