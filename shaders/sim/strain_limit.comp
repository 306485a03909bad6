// Step 6 of METHOD.md section 2.7, one invocation per strand: the strand contacts' corrections
// (contact_solve.comp: each particle moves by the mean of what its segments sent), strain
// limiting in one sweep from root to tip (paper section 3.2: each segment is fixed against an
// already final parent, so no iteration), pushing out of the head (its distance field, or its
// spheres), Coulomb friction against the head and DFTL (Mueller et al. 2012) on the
// strain-limit correction, as limitStrainStrand in sim/solver/cpu_steps.cpp. The sweep is sequential by nature; a
// strand is one invocation and the particle's parent stays in registers. Built once for each
// kind of head, CSM_HEAD_FIELD or not: llvmpipe would run both heads' pushes for every particle.
#include "sim/common.glsl"

layout(local_size_x = CSM_STRAND_GROUP) in;

layout(binding = CSM_TEX_REST) uniform samplerBuffer restTex;
layout(std430, binding = CSM_BIND_POSITION) buffer Position { vec4 pos[]; };
layout(std430, binding = CSM_BIND_VELOCITY) buffer Velocity { vec4 vel[]; };
layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_STRAND_ORDER) readonly buffer StrandOrder { uint strandOrder[]; };
layout(std430, binding = CSM_BIND_SPHERES) readonly buffer Spheres { vec4 spheres[]; };
layout(std430, binding = CSM_BIND_STRAND_STIFFNESS) readonly buffer StrandStiffness {
  vec4 strandStiffness[];
};
layout(std430, binding = CSM_BIND_CORRECTION) readonly buffer Correction { vec4 correction[]; };

uniform uint substep;

#include "sim/head_push.glsl"

// Strand s: the sweep from its first free particle to its tip (sweepParticle), and held at both
// ends, the sweeps back and forth (limitToward). The float twin of limitStrainStrand in
// sim/solver/cpu_steps.cpp.
void limitStrainStrand(uint s) {
  uint a = strandFirst[s];
  int n = int(strandFirst[s + 1u] - a);
  vec4 stiff = strandStiffness[s];
  int pinned = pinnedOf(stiff);
  int first = max(1, pinned);
  int end = n - (tipHeldOf(stiff) ? 1 : 0);  // a held tip stays where the head put it
  if (end <= first) return;

  Substep st = S[substep];
  bool contacts = P.strandContacts != 0u;
  uint sphereBase = substep * uint(P.headSpheres);

  vec3 restPrev = texelFetch(restTex, int(a) + first - 1).xyz;
  vec3 xPrev = pos[a + uint(first - 1)].xyz;
  vec3 vPrev = vel[a + uint(first - 1)].xyz;
  bool prevFree = first - 1 >= pinned;  // DFTL only corrects free particles
  for (int i = first; i < end; ++i) {
    uint p = a + uint(i);
    vec3 restHere = texelFetch(restTex, int(p)).xyz;
    vec3 x = pos[p].xyz;
    vec3 v = vel[p].xyz;
    vec4 c = vec4(0.0);
    if (contacts) {
      c = correction[2u * (p - 1u) + 1u];
      if (i + 1 < n) c += correction[2u * p];
    }
    sweepParticle(restHere, restPrev, contacts, c, xPrev, prevFree, st, sphereBase, x, v, vPrev);
    vel[p - 1u] = vec4(vPrev, 0.0);
    pos[p] = vec4(x, 1.0);
    restPrev = restHere;
    xPrev = x;
    vPrev = v;
    prevFree = i >= pinned;
  }
  vel[a + uint(end - 1)] = vec4(vPrev, 0.0);
  // Held at both ends: sweeps back from the tip and forth from the root (limitToward).
  bool tied = P.strainLimiting != 0u && end < n;
  for (int pass = 0; tied && pass < CSM_TIED_SWEEPS; ++pass) {
    for (int back = 0; tied && back < 2; ++back) {
      bool moved = false;
      for (int k = 0; k < end - first; ++k) {
        int i = back == 0 ? end - 1 - k : first + k;
        uint p = a + uint(i), q = back == 0 ? p + 1u : p - 1u;
        vec3 x = pos[p].xyz, v = vel[p].xyz;
        float rest = length(texelFetch(restTex, int(p)).xyz - texelFetch(restTex, int(q)).xyz);
        if (limitToward(x, v, pos[q].xyz, rest, st.h)) {
          pos[p] = vec4(x, 1.0);
          vel[p] = vec4(v, 0.0);
          moved = true;
        }
      }
      tied = moved;
    }
  }
  // What the sweeps left: one more from the root, each particle within reach of its parent and
  // of the held tip (limitStrainStrand's last sweep).
  if (P.strainLimiting == 0u || end >= n) return;
  float grow = 1.0 + P.strainLimit, reach = 0.0;
  for (int i = first - 1; i < end; ++i)
    reach += grow * length(texelFetch(restTex, int(a) + i + 1).xyz -
                           texelFetch(restTex, int(a) + i).xyz);
  vec3 tip = pos[a + uint(end)].xyz;
  vec3 parent = pos[a + uint(first - 1)].xyz;
  for (int i = first; i < end; ++i) {
    uint p = a + uint(i);
    float segment = grow * length(texelFetch(restTex, int(p)).xyz - texelFetch(restTex, int(p) - 1).xyz);
    reach -= segment;
    vec3 x = pos[p].xyz;
    vec3 to = intoBothBalls(x, parent, segment, tip, reach);
    vel[p] = vec4(vel[p].xyz + (to - x) / st.h, 0.0);
    pos[p] = vec4(to, 1.0);
    parent = to;
  }
}

void main() {
  uint id = globalIndex();
  if (id >= P.strands) return;
  limitStrainStrand(strandOrder[id]);
}
