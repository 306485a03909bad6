// Strand contacts, list pass (DESIGN.md section 1.7), one invocation per segment: sorts the
// segment's candidates (pair_scatter.comp left them, with their flags and contact distances,
// in its range in no order) into its list, the same range of this frame's half of the lists,
// in ascending order of the other segment; and counts crossings: pairs, from the lower
// segment's side, whose orientation flipped against last frame's list (csm::findCandidates
// does the same on the CPU). Every candidate has its place: no list is cut short.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(binding = CSM_TEX_GRID_START) uniform usamplerBuffer gridStartTex;

layout(std430, binding = CSM_BIND_SEGMENT_BASE) readonly buffer SegmentBase { uint segBase[]; };
layout(std430, binding = CSM_BIND_PAIR_SIDES) readonly buffer PairSides { uvec2 pairSides[]; };
layout(std430, binding = CSM_BIND_CANDIDATES) buffer Candidates { uvec2 candidates[]; };
layout(std430, binding = CSM_BIND_CANDIDATE_RANGE) buffer CandidateRange {
  uvec2 candidateRange[];
};
layout(std430, binding = CSM_BIND_COUNTERS) buffer Counters { uint counters[]; };

void main() {
  uint a = globalIndex();
  if (a >= P.counts.x) return;
  uint here = P.grid.w * P.counts.x + a, before = (1u - P.grid.w) * P.counts.x + a;
  // This frame's half of the lists: two sides per slot of the pair list.
  uint base = P.grid.w * 2u * P.grid.z + segBase[a];
  uint n = 0u;
  // No candidates when the grid or the pair list did not fit this frame; the counters say so
  // (and keep the count of such frames).
  uint total = texelFetch(gridStartTex, int(P.grid.x + 1u)).x;
  bool fits = total <= P.grid.y && counters[CSM_COUNTER_PAIR_LIST] <= P.grid.z;
  if (a == 0u && !fits) ++counters[CSM_COUNTER_OVERFLOWS];
  if (fits) {
    n = segBase[a + 1u] - segBase[a];
    for (uint k = 0u; k < n; ++k) {
      uvec2 c = pairSides[segBase[a] + k];
      uint i = k;
      while (i > 0u && (candidates[base + i - 1u].x & kIndex) > (c.x & kIndex)) {
        candidates[base + i] = candidates[base + i - 1u];
        --i;
      }
      candidates[base + i] = c;
    }
  }
  candidateRange[here] = uvec2(base, n);
  // Crossings: both lists are in ascending order.
  uint crossings = 0u, close = 0u;
  uvec2 last = candidateRange[before];
  uint j = 0u;
  for (uint k = 0u; k < n; ++k) {
    uvec2 c = candidates[base + k];
    uint b = c.x & kIndex;
    if (b < a) continue;
    while (j < last.y && (candidates[last.x + j].x & kIndex) < b) ++j;
    if (j < last.y && (candidates[last.x + j].x & kIndex) == b &&
        crossed(candidates[last.x + j].x >> uint(CSM_CANDIDATE_SHIFT),
                c.x >> uint(CSM_CANDIDATE_SHIFT))) {
      ++crossings;
      if (uintBitsToFloat(c.y) < 2.0 * P.stepping.z) ++close;  // a rest distance
    }
  }
  if (crossings > 0u) atomicAdd(counters[CSM_COUNTER_CROSSINGS], crossings);
  if (close > 0u) atomicAdd(counters[CSM_COUNTER_CROSSINGS_CLOSE], close);
}
