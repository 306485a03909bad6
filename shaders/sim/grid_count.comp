// Collision pass, grid build 1/3 (counting sort: count), one invocation per segment: the
// segment counts itself into the bucket of every cell of its padded box that it passes within
// the pad of (clipToCell; Fig. 1: 5 on average; segmentCells caps the box). Integer atomics:
// the counts do not depend on the order.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

#include "sim/particle_reads.glsl"

layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_GRID_COUNT) buffer GridCount { uint gridCount[]; };
// A search for the contact measures alone takes 1 strand in measureStride (inMeasureSample).
uniform uint measureStride;
layout(std430, binding = CSM_BIND_COUNTERS) buffer Counters { uint counters[]; };

void main() {
  uint i = globalIndex();
  if (i + 1u >= P.particles || particleStrand[i] != particleStrand[i + 1u]) return;
  if (!inMeasureSample(particleStrand[i], measureStride)) return;
  vec3 p0 = readPosition(i).xyz, p1 = readPosition(i + 1u).xyz;
  ivec3 lo, hi;
  if (!segmentCells(p0, p1, lo, hi)) {
    atomicAdd(counters[CSM_COUNTER_OVERSIZE], 1u);
    return;
  }
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
        vec3 q0, q1;
        if (clipToCell(p0, p1, ivec3(x, y, z), q0, q1))
          atomicAdd(gridCount[bucketOf(cellKey(ivec3(x, y, z)))], 1u);
      }
}
