// Collision pass, grid build 1/6, one invocation per particle index: the midpoint and half
// length of each segment (segment i joins particles i and i+1 of one strand), and the
// longest segment, whose length sets the cell size. Positive floats order like their bit
// patterns, so an integer atomicMax gives the maximum whatever the order: deterministic.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(std430, binding = CSM_BIND_POSITION) readonly buffer Position { vec4 pos[]; };
layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_SEGMENT_DATA) writeonly buffer SegmentData { vec4 segData[]; };
layout(std430, binding = CSM_BIND_COUNTERS) buffer Counters { uint counters[]; };

shared uint longest[CSM_PARTICLE_GROUP];

void main() {
  uint i = globalIndex();
  uint lid = gl_LocalInvocationID.x;
  uint bits = 0u;
  if (i + 1u < P.counts.x && particleStrand[i] == particleStrand[i + 1u]) {
    vec3 p0 = pos[i].xyz, p1 = pos[i + 1u].xyz;
    float len = length(p1 - p0);
    segData[i] = vec4(0.5 * (p0 + p1), 0.5 * len);
    bits = floatBitsToUint(len);
  }
  longest[lid] = bits;
  barrier();
  for (uint stride = CSM_PARTICLE_GROUP / 2u; stride > 0u; stride >>= 1u) {
    if (lid < stride) longest[lid] = max(longest[lid], longest[lid + stride]);
    barrier();
  }
  if (lid == 0u && longest[0] != 0u) atomicMax(counters[CSM_COUNTER_LONGEST], longest[0]);
}
