// One strand-contact iteration before the next (collision.iterations > 1), one invocation per
// strand, as csm::applyCorrections: each particle but the root moves by the mean of what its
// segments sent (contact_solve.comp), its velocity by that over h. The last iteration's
// corrections are applied by strain_limit.comp instead, at the head of its sweep. The held
// particles were sent nothing (their inverse mass is 0).
#include "sim/common.glsl"

layout(local_size_x = CSM_STRAND_GROUP) in;

layout(std430, binding = CSM_BIND_POSITION) buffer Position { vec4 pos[]; };
layout(std430, binding = CSM_BIND_VELOCITY) buffer Velocity { vec4 vel[]; };
layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_CORRECTION) readonly buffer Correction { vec4 correction[]; };

uniform uint substep;

void main() {
  uint s = globalIndex();
  if (s >= P.strands) return;
  uint a = strandFirst[s];
  uint n = strandFirst[s + 1u] - a;
  float h = S[substep].h;
  for (uint i = 1u; i < n; ++i) {
    uint p = a + i;
    vec4 c = correction[2u * (p - 1u) + 1u];
    if (i + 1u < n) c += correction[2u * p];
    if (c.w > 0.0) {
      vec3 moved = c.xyz / c.w;
      pos[p].xyz += moved;
      vel[p].xyz += moved / h;
    }
  }
}
