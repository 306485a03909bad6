// Strand contacts as the paper's penalty forces (collision.contact_model = penalty; METHOD.md
// section 3.1; the CPU reference is csm::penaltyVelocities in sim/solver/contacts.cpp), one
// invocation per segment, where the substep ends (after the strain limit): each of the
// segment's candidates closer than its contact distance d0 asks for an acceleration
// k (d0 - separation) along the contact normal, less c times the approach speed along it (never
// a pull), and Coulomb friction against the contact points' relative sliding, up to mu times the
// normal change of velocity and half the sliding. Each end of the segment takes its barycentric
// share (the held ends none); contact_apply.comp (CSM_PENALTY) adds both segments' shares to a
// particle's velocity, so the next substep's prediction feels them. Both sides of a pair
// evaluate it with the lower index first; the sums run in list order.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

#include "sim/particle_reads.glsl"

#include "sim/candidate_views.glsl"
layout(std430, binding = CSM_BIND_CANDIDATE_RANGE) readonly buffer CandidateRange {
  uvec2 candidateRange[];
};
layout(std430, binding = CSM_BIND_CORRECTION) writeonly buffer Correction { vec4 correction[]; };
layout(std430, binding = CSM_BIND_SEGMENT_ORDER) readonly buffer SegmentOrder {
  uint segmentOrder[];
};

uniform uint substep;

vec3 fetchPos(uint i) { return readPosition(i).xyz; }
vec3 fetchVel(uint i) { return readVelocity(i).xyz; }

void main() {
  if (globalIndex() >= P.particles) return;
  uint a = segmentOrder[globalIndex()];
  uvec2 range = candidateRange[P.listHalf * P.particles + a];
  vec3 dv0 = vec3(0.0), dv1 = vec3(0.0);
  if (range.y > 0u) {
    float h = S[substep].h;
    float k = P.penaltyStiffness, damping = P.penaltyDamping, mu = P.friction;
    vec3 a0 = fetchPos(a), a1 = fetchPos(a + 1u);
    vec3 va0 = fetchVel(a), va1 = fetchVel(a + 1u);
    bool held0 = readInverseMass(a) <= 0.0, held1 = readInverseMass(a + 1u) <= 0.0;
    for (uint j = 0u; j < range.y; ++j) {
      uvec2 c = candidateAt(range.x + j);
      uint b = c.x & kIndex;
      float d0 = uintBitsToFloat(c.y);
      vec3 b0 = fetchPos(b), b1 = fetchPos(b + 1u);
      vec3 vb0 = fetchVel(b), vb1 = fetchVel(b + 1u);
      // The lower index first; the operands chosen before the calls (see contact_solve.comp).
      bool lower = a < b;
      vec3 p0 = lower ? a0 : b0, p1 = lower ? a1 : b1;
      vec3 q0 = lower ? b0 : a0, q1 = lower ? b1 : a1;
      vec3 vp0 = lower ? va0 : vb0, vp1 = lower ? va1 : vb1;
      vec3 vq0 = lower ? vb0 : va0, vq1 = lower ? vb1 : va1;
      float s, t, separation;
      float d = sqrt(closestSegmentPoints(p0, p1, q0, q1, s, t));
      vec3 nrm = contactNormal(p0, p1, q0, q1, s, t, d, keptSide(c.x >> uint(CSM_CANDIDATE_SHIFT)),
                               separation);
      float depth = d0 - separation;
      // isnan and isinf too: a segment gone non-finite pushes no other.
      if (isnan(depth) || isinf(depth) || depth <= 0.0) continue;
      vec3 rel = mix(vp0, vp1, s) - mix(vq0, vq1, t);
      float approach = dot(rel, nrm);  // negative when closing
      float push = h * (k * depth - damping * approach);
      if (!(push > 0.0)) continue;  // a penalty never pulls
      vec3 slide = rel - approach * nrm;
      float slideLen = length(slide);
      float taken = min(0.5 * slideLen, mu * push);
      vec3 dv = push * nrm;
      if (slideLen > 1e-15) dv -= slide * (taken / slideLen);
      if (!lower) dv = -dv;
      float g0 = lower ? 1.0 - s : 1.0 - t, g1 = lower ? s : t;
      if (!held0) dv0 += g0 * dv;
      if (!held1) dv1 += g1 * dv;
    }
  }
  correction[2u * a] = vec4(dv0, 0.0);
  correction[2u * a + 1u] = vec4(dv1, 0.0);
}
