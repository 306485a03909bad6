// Strand contacts, one substep (METHOD.md section 3.1; the CPU reference is csm::solveContacts
// in sim/solver/contacts.cpp), one invocation per segment, after shape matching: each of the
// segment's candidates closer than its contact distance is a compliant position constraint
// (XPBD, one iteration of collision.iterations: lambda = -C / (W + compliance / h^2);
// contact_apply.comp moves the particles between two), held to the side it was
// listed on when skew (contactNormal), with Coulomb friction on
// the contact points' relative sliding this step, removed up to mu times the normal
// correction. With collision.solve = sweep the segment takes its list in order, moving its own
// two ends by each pair's share before the next pair (Gauss-Seidel within the list, Jacobi
// between segments: the other segments stay where the iteration found them), and writes what
// the sweep moved its ends by; with jacobi, the sum of what its pairs ask from where the
// iteration began, and how many asked. strain_limit.comp moves each particle by the mean of
// what its segments sent. Both sides of a pair evaluate it with the lower index first; the
// list's order fixes the sweep's and the sums'.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

#include "sim/particle_reads.glsl"

#include "sim/candidate_views.glsl"
layout(std430, binding = CSM_BIND_CANDIDATE_RANGE) readonly buffer CandidateRange {
  uvec2 candidateRange[];
};
layout(std430, binding = CSM_BIND_CORRECTION) writeonly buffer Correction { vec4 correction[]; };
// The segments by candidate count (segment_order.comp): invocation i takes segment
// segmentOrder[i], so a SIMD group's lists are of like length.
layout(std430, binding = CSM_BIND_SEGMENT_ORDER) readonly buffer SegmentOrder {
  uint segmentOrder[];
};

uniform uint substep;

// The most a pair moves one end of a segment in a sweep, in units of the pair's depth: near a
// held end a pair asks the free end for depth / s (CSM_CONTACT_LEVER, shared with
// sim/solver/contacts.cpp, whose kLever says why).
const float kLever = CSM_CONTACT_LEVER;
// How far (m) a sweep must move an end to count as one of the particle's segments (csm::
// kFullWeight).
const float kFullWeight = CSM_FULL_WEIGHT;


vec3 fetchPos(uint i) { return readPosition(i).xyz; }
vec3 fetchVel(uint i) { return readVelocity(i).xyz; }
// Inverse masses of segment i's two particles (0 for those the head holds).
vec2 inverseMasses(uint i) {
  return vec2(readInverseMass(i), readInverseMass(i + 1u));
}

void main() {
  if (globalIndex() >= P.particles) return;
  uint a = segmentOrder[globalIndex()];
  uint here = P.listHalf * P.particles + a;
  uvec2 range = candidateRange[here];
  uint n = range.y;
  // The segment's own ends, and their velocities, as its sweep has moved them so far (a move
  // of dx changes the velocity by dx / h): each pair's friction takes what sliding the pairs
  // before it left, not the same sliding again. The other segments stay where the iteration
  // found them; jacobi (collision.solve) evaluates every pair from there too.
  bool sweep = P.sweepSolve > 0.5;
  vec3 moved0 = vec3(0.0), moved1 = vec3(0.0);  // what the pairs moved the ends by, in order
  float count = 0.0;                            // how many did
  if (n > 0u) {
    float h = S[substep].h;
    float tilde = P.compliance / (h * h);
    float mu = P.friction;
    vec3 a0 = fetchPos(a), a1 = fetchPos(a + 1u);
    vec3 va0 = fetchVel(a), va1 = fetchVel(a + 1u);
    vec2 wa = inverseMasses(a);
    for (uint k = 0u; k < n; ++k) {
      uvec2 c = candidateAt(range.x + k);
      uint b = c.x & kIndex;
      float d0 = uintBitsToFloat(c.y);
      vec3 b0 = fetchPos(b), b1 = fetchPos(b + 1u);
      // The pair as both of its segments see it: the lower index first (s on it). The
      // operands are chosen before the call: under a SIMD mask both sides of a ?: would run it.
      bool lower = a < b;
      vec3 p0 = lower ? a0 : b0, p1 = lower ? a1 : b1;
      vec3 q0 = lower ? b0 : a0, q1 = lower ? b1 : a1;
      float s, t, separation;
      float d = sqrt(closestSegmentPoints(p0, p1, q0, q1, s, t));
      vec3 nrm = contactNormal(p0, p1, q0, q1, s, t, d, keptSide(c.x >> uint(CSM_CANDIDATE_SHIFT)),
                               separation);
      float C = separation - d0;
      // isnan and isinf as well: a compiler may assume that comparisons see no NaN, and a
      // pair kept from the list before (a search over the buffers) may have a segment that is
      // no longer finite, which must not spread to this one.
      if (isnan(C) || isinf(C) || C >= 0.0) continue;
      vec2 wb = inverseMasses(b);
      vec2 wp = lower ? wa : wb, wq = lower ? wb : wa;
      float W = (1.0 - s) * (1.0 - s) * wp.x + s * s * wp.y + (1.0 - t) * (1.0 - t) * wq.x +
                t * t * wq.y;
      if (W <= 0.0) continue;  // both held
      float lambda = -C / (W + tilde);
      vec3 vb0 = fetchVel(b), vb1 = fetchVel(b + 1u);
      vec3 vp = lower ? mix(va0, va1, s) : mix(vb0, vb1, s);
      vec3 vq = lower ? mix(vb0, vb1, t) : mix(va0, va1, t);
      vec3 slide = h * (vp - vq);
      vec3 tangent = slide - dot(slide, nrm) * nrm;
      float slideLen = length(tangent);
      float taken = min(slideLen, mu * W * lambda);
      tangent = slideLen > 1e-15 ? tangent * (taken / (slideLen * W)) : vec3(0.0);
      vec3 push = lambda * nrm - tangent;
      if (!lower) push = -push;
      float g0 = lower ? 1.0 - s : 1.0 - t, g1 = lower ? s : t;
      // The sweep moves neither end further than kLever times the pair's depth.
      float most = lambda * max(g0 * wa.x, g1 * wa.y);
      if (sweep && most > kLever * -C) push *= kLever * -C / most;
      vec3 move0 = push * (g0 * wa.x), move1 = push * (g1 * wa.y);
      moved0 += move0;
      moved1 += move1;
      count += 1.0;
      if (sweep) {
        a0 += move0;
        a1 += move1;
        va0 += move0 / h;
        va1 += move1 / h;
      }
    }
  }
  // The sweep sends where it left each end, as one segment (kFullWeight); jacobi the sum over
  // its pairs, as that many. strain_limit.comp divides by the weights.
  float l0 = sweep ? min(length(moved0) / kFullWeight, 1.0) : count;
  float l1 = sweep ? min(length(moved1) / kFullWeight, 1.0) : count;
  correction[2u * a] = vec4(sweep ? moved0 * l0 : moved0, l0);
  correction[2u * a + 1u] = vec4(sweep ? moved1 * l1 : moved1, l1);
}
