// Step 6 of METHOD.md section 2.7 on the per-particle path, for modes with strand contacts
// (without them strand_step.comp sweeps in the same pass): one invocation per particle, whole
// strands to a work group (strand_group.glsl). Each slot loads its particle, its rest position
// and the contacts' correction sent to it (contact_solve.comp) into shared memory, the root's
// slot sweeps the strand there (head_push.glsl, as strain_limit.comp), and each slot stores its
// particle back.
#include "sim/common.glsl"

#include "sim/particle_reads.glsl"
layout(std430, binding = CSM_BIND_POSITION) buffer Position { vec4 pos[]; };
layout(std430, binding = CSM_BIND_VELOCITY) buffer Velocity { vec4 vel[]; };
layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_SPHERES) readonly buffer Spheres { vec4 spheres[]; };
layout(std430, binding = CSM_BIND_STRAND_STIFFNESS) readonly buffer StrandStiffness {
  vec4 strandStiffness[];
};
layout(std430, binding = CSM_BIND_CORRECTION) readonly buffer Correction { vec4 correction[]; };

uniform uint substep;

#define CSM_SWEEP
#include "sim/head_push.glsl"
#include "sim/strand_group.glsl"

void main() {
  Slot o = groupSlot();
  uint lid = gl_LocalInvocationID.x;
  vec4 c = vec4(0.0);
  if (o.live && o.j > 0 && P.strandContacts != 0u) {
    c = correction[2u * (o.p - 1u) + 1u];
    if (o.j + 1 < o.n) c += correction[2u * o.p];
  }
  shA[lid] = o.live ? pos[o.p] : vec4(0.0);
  shB[lid] = o.live ? vel[o.p] : vec4(0.0);
  shC[lid] = o.live ? readRest(o.p) : vec4(0.0);
  shD[lid] = c;
  barrier();
  sweepStrands(o, substep);
  if (o.live) {
    pos[o.p] = vec4(shA[lid].xyz, 1.0);
    vel[o.p] = vec4(shB[lid].xyz, 0.0);
  }
}
