// Strand contacts, list pass (DESIGN.md section 1.7), one invocation per segment: sorts the
// segment's candidate pairs (pair_scatter.comp left them in its range in no order) into its
// list, the same range of this frame's half of the lists, in ascending order; gives each its
// flags and contact distance; and counts crossings: pairs, from the lower segment's side,
// whose orientation flipped against last frame's list (csm::findCandidates does the same on
// the CPU). Every candidate has its place: no list is cut short.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(binding = CSM_TEX_POSITION) uniform samplerBuffer posTex;
layout(binding = CSM_TEX_REST) uniform samplerBuffer restTex;
layout(binding = CSM_TEX_GRID_START) uniform usamplerBuffer gridStartTex;

layout(std430, binding = CSM_BIND_SEGMENT_BASE) readonly buffer SegmentBase { uint segBase[]; };
layout(std430, binding = CSM_BIND_PAIR_SIDES) readonly buffer PairSides { uint pairSides[]; };
layout(std430, binding = CSM_BIND_CANDIDATES) buffer Candidates { uvec2 candidates[]; };
layout(std430, binding = CSM_BIND_CANDIDATE_RANGE) buffer CandidateRange {
  uvec2 candidateRange[];
};
layout(std430, binding = CSM_BIND_COUNTERS) buffer Counters { uint counters[]; };

vec3 fetchPos(uint i) { return texelFetch(posTex, int(i)).xyz; }
vec3 fetchRest(uint i) { return texelFetch(restTex, int(i)).xyz; }

void main() {
  uint a = globalIndex();
  if (a >= P.counts.x) return;
  uint here = P.grid.w * P.counts.x + a, before = (1u - P.grid.w) * P.counts.x + a;
  // This frame's half of the lists: two sides per slot of the pair list.
  uint base = P.grid.w * 2u * P.grid.z + segBase[a];
  uint n = 0u;
  // No candidates when the grid or the pair list did not fit this frame.
  uint total = texelFetch(gridStartTex, int(P.grid.x + 1u)).x;
  if (total <= P.grid.y && counters[CSM_COUNTER_PAIR_LIST] <= P.grid.z) {
    n = segBase[a + 1u] - segBase[a];
    for (uint k = 0u; k < n; ++k) {
      uint b = pairSides[segBase[a] + k];
      uint i = k;
      while (i > 0u && candidates[base + i - 1u].x > b) {
        candidates[base + i].x = candidates[base + i - 1u].x;
        --i;
      }
      candidates[base + i].x = b;
    }
    // Flags and contact distance, the pair as CpuSolver sees it: lower index first (s on it,
    // t on the other). Pairs the groom put closer than 2r keep their rest distance (the rest
    // positions are in the head frame, which moves rigidly).
    float twoR = 2.0 * P.stepping.z;
    vec3 a0 = fetchPos(a), a1 = fetchPos(a + 1u);
    vec3 restA0 = fetchRest(a), restA1 = fetchRest(a + 1u);
    for (uint k = 0u; k < n; ++k) {
      uint b = candidates[base + k].x;
      bool lower = a < b;
      vec3 b0 = fetchPos(b), b1 = fetchPos(b + 1u);
      vec3 p0 = lower ? a0 : b0, p1 = lower ? a1 : b1;
      vec3 q0 = lower ? b0 : a0, q1 = lower ? b1 : a1;
      float s, t;
      float dist = sqrt(closestSegmentPoints(p0, p1, q0, q1, s, t));
      uint flags = pairFlags(p0, p1, q0, q1, s, t, dist, twoR);
      vec3 rb0 = fetchRest(b), rb1 = fetchRest(b + 1u);
      float rs, rt;
      float d0 = min(twoR, sqrt(closestSegmentPoints(lower ? restA0 : rb0, lower ? restA1 : rb1,
                                                     lower ? rb0 : restA0, lower ? rb1 : restA1,
                                                     rs, rt)));
      candidates[base + k] = uvec2(b | (flags << uint(CSM_CANDIDATE_SHIFT)), floatBitsToUint(d0));
    }
  }
  candidateRange[here] = uvec2(base, n);
  // Crossings: both lists are in ascending order.
  uint crossings = 0u;
  uvec2 last = candidateRange[before];
  uint j = 0u;
  for (uint k = 0u; k < n; ++k) {
    uvec2 c = candidates[base + k];
    uint b = c.x & kIndex;
    if (b < a) continue;
    while (j < last.y && (candidates[last.x + j].x & kIndex) < b) ++j;
    if (j < last.y && (candidates[last.x + j].x & kIndex) == b &&
        crossed(candidates[last.x + j].x >> uint(CSM_CANDIDATE_SHIFT),
                c.x >> uint(CSM_CANDIDATE_SHIFT)))
      ++crossings;
  }
  if (crossings > 0u) atomicAdd(counters[CSM_COUNTER_CROSSINGS], crossings);
}
