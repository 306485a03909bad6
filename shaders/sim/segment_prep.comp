// Collision pass, grid build 1/6, one invocation per strand: the midpoint and half length of
// each of its segments (segment i joins particles i and i+1), and the longest segment, whose
// length sets the cell size. Positive floats order like their bit patterns, so an integer
// atomicMax gives the maximum whatever the order: deterministic. One atomic per strand, not
// per segment, and no barriers.
#include "sim/common.glsl"

layout(local_size_x = CSM_STRAND_GROUP) in;

layout(std430, binding = CSM_BIND_POSITION) readonly buffer Position { vec4 pos[]; };
layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_SEGMENT_DATA) writeonly buffer SegmentData { vec4 segData[]; };
layout(std430, binding = CSM_BIND_COUNTERS) buffer Counters { uint counters[]; };

void main() {
  uint s = globalIndex();
  if (s >= P.counts.y) return;
  uint a = strandFirst[s], b = strandFirst[s + 1u];
  if (b <= a + 1u) return;
  float longest = 0.0;
  vec3 p0 = pos[a].xyz;
  for (uint i = a; i + 1u < b; ++i) {
    vec3 p1 = pos[i + 1u].xyz;
    float len = length(p1 - p0);
    segData[i] = vec4(0.5 * (p0 + p1), 0.5 * len);
    longest = max(longest, len);
    p0 = p1;
  }
  atomicMax(counters[CSM_COUNTER_LONGEST], floatBitsToUint(longest));
}
