// Strand contacts, segment order (after the per-segment scan), one invocation per segment:
// within each work group's run of CSM_PARTICLE_GROUP segments, the segments by how many
// candidates they have, most first, for the list pass and the contact solve, which run one
// invocation per segment and loop over its candidates. The SIMD lanes of a group wait for its
// longest list, and neighbouring segments' lists differ: on Fig. 1's rest groom, groups of 8
// lanes in index order do 2.1x the work of their lists, 1.3x in this order. The order stays
// within the run (a few strands), so what the invocations read stays as close together in
// memory as in index order; a global order by count does no better on llvmpipe (its scattered
// reads cost more than the lanes save). The rank of each segment counts the longer lists of
// its run (ties by index): no atomics, the same order every time.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(std430, binding = CSM_BIND_SEGMENT_BASE) readonly buffer SegmentBase { uint segBase[]; };
layout(std430, binding = CSM_BIND_SEGMENT_ORDER) writeonly buffer SegmentOrder {
  uint segmentOrder[];
};

shared uint runCount[CSM_PARTICLE_GROUP];

void main() {
  uint a = globalIndex();
  uint lid = gl_LocalInvocationID.x;
  bool valid = a < P.particles;
  uint mine = valid ? segBase[a + 1u] - segBase[a] : 0u;
  runCount[lid] = mine;
  barrier();
  if (!valid) return;
  // Invocations past the last segment are at the run's end, and every valid one ranks before
  // them: their count is 0 and their index higher.
  uint rank = 0u;
  for (uint j = 0u; j < uint(CSM_PARTICLE_GROUP); ++j) {
    uint other = runCount[j];
    if (other > mine || (other == mine && j < lid)) ++rank;
  }
  segmentOrder[a - lid + rank] = a;
}
