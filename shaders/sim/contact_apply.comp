// One strand-contact iteration before the next (collision.iterations > 1), one invocation per
// particle, as csm::applyCorrections: each particle but the root moves by the mean of what its
// segments sent (contact_solve.comp), its velocity by that over h. The last iteration's
// corrections are applied by the strain limit's sweep instead (strain_limit.comp,
// strand_strain.comp). The held particles were sent nothing (their inverse mass is 0).
// CSM_PENALTY: the penalty model's changes of velocity (contact_penalty.comp), where the substep
// ends: the sum of what both segments sent is added to the velocity, as
// csm::applyPenalty does.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(std430, binding = CSM_BIND_POSITION) buffer Position { vec4 pos[]; };
layout(std430, binding = CSM_BIND_VELOCITY) buffer Velocity { vec4 vel[]; };
layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_CORRECTION) readonly buffer Correction { vec4 correction[]; };

uniform uint substep;

void main() {
  uint p = globalIndex();
  if (p >= P.particles) return;
  uint s = particleStrand[p];
  uint a = strandFirst[s], b = strandFirst[s + 1u];
  if (p == a) return;
  vec4 c = correction[2u * (p - 1u) + 1u];
  if (p + 1u < b) c += correction[2u * p];
#ifdef CSM_PENALTY
  vel[p].xyz += c.xyz;
#else
  if (c.w > 0.0) {
    vec3 moved = c.xyz / c.w;
    float h = S[substep].h;
    pos[p].xyz += moved;
    vel[p].xyz += moved / h;
  }
#endif
}
