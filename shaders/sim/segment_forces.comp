// Collision pass, last step, one invocation per segment: the sum of its partial forces (one
// per cell it entered, written by contacts.comp) in cell order, so the sum is the same
// whatever the schedule. The particles gather from these slots in predict.comp.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(binding = CSM_TEX_GRID_START) uniform usamplerBuffer gridStartTex;

layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_SEGMENT_BASE) readonly buffer SegmentBase { uint segBase[]; };
layout(std430, binding = CSM_BIND_PARTIAL_FORCE) readonly buffer PartialForce {
  vec4 partialForce[];
};
layout(std430, binding = CSM_BIND_SEGMENT_FORCE) writeonly buffer SegmentForce { vec4 segForce[]; };
layout(std430, binding = CSM_BIND_SEGMENT_CONTACTS) writeonly buffer SegmentContacts {
  uint segContacts[];
};

void main() {
  uint i = globalIndex();
  if (i + 1u >= P.counts.x || particleStrand[i] != particleStrand[i + 1u]) return;
  vec4 f0 = vec4(0.0), f1 = vec4(0.0);
  // No grid this frame (it did not fit): no forces.
  uint total = texelFetch(gridStartTex, int(P.grid.x + 1u)).x;
  if (total <= P.grid.y) {
    for (uint k = segBase[i]; k < segBase[i + 1u]; ++k) {
      f0 += partialForce[2u * k];
      f1 += partialForce[2u * k + 1u];
    }
  }
  segForce[2u * i] = vec4(f0.xyz, 0.0);
  segForce[2u * i + 1u] = vec4(f1.xyz, 0.0);
  segContacts[i] = uint(f0.w);
}
