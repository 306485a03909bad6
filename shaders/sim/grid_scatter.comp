// Collision pass, grid build 3/3 (counting sort: scatter), one invocation per segment: an
// entry in each of its cells' buckets, all that the candidate pass tests a candidate on in
// one texel (packEntry: the cell's key, the segment, and the padded box of its piece in the
// cell, within the cell). Counting each bucket back down returns the counts to zero for the
// next frame (no clear needed), also when the entries do not fit: then nothing is written past the
// capacity and the candidate pass skips the frame (GpuSolver grows the buffer when it sees the
// total). The order within a bucket depends on the schedule; nothing downstream depends on it
// (candidate_lists.comp sorts each segment's list).
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

#include "sim/particle_reads.glsl"

layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_GRID_COUNT) buffer GridCount { uint gridCount[]; };
// A search for the contact measures alone takes 1 strand in measureStride (inMeasureSample).
uniform uint measureStride;
layout(std430, binding = CSM_BIND_GRID_START) readonly buffer GridStart { uint gridStart[]; };
layout(binding = CSM_IMAGE_ENTRIES, rgba32ui) writeonly uniform uimageBuffer entries;

void main() {
  uint i = globalIndex();
  if (i + 1u >= P.particles || particleStrand[i] != particleStrand[i + 1u]) return;
  if (!inMeasureSample(particleStrand[i], measureStride)) return;
  vec3 p0 = readPosition(i).xyz, p1 = readPosition(i + 1u).xyz;
  ivec3 lo, hi;
  if (!segmentCells(p0, p1, lo, hi)) return;
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
        ivec3 cell = ivec3(x, y, z);
        vec3 q0, q1;
        if (!clipToCell(p0, p1, cell, q0, q1)) continue;
        vec3 low, high;
        segmentBox(q0, q1, low, high);
        uint key = cellKey(cell);
        uint bucket = bucketOf(key);
        uint slot = gridStart[bucket] + atomicAdd(gridCount[bucket], 0xffffffffu) - 1u;
        if (slot < P.entryCapacity) imageStore(entries, int(slot), packEntry(key, i, low, high, cell));
      }
}
