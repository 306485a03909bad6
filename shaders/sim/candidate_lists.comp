// Strand contacts, list pass (DESIGN.md section 1.7), one invocation per segment: merges the
// slots candidates.comp wrote for the segment's cells (each in ascending order) into the
// segment's list in this frame's half of the lists, in ascending order, keeping the
// CSM_SEGMENT_CANDIDATES lowest indices (the others are counted as dropped, never silently),
// and counts crossings: pairs, from the lower segment's side, whose orientation flipped
// against last frame's list (csm::findCandidates does the same on the CPU).
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(binding = CSM_TEX_GRID_START) uniform usamplerBuffer gridStartTex;

layout(std430, binding = CSM_BIND_SEGMENT_BASE) readonly buffer SegmentBase { uint segBase[]; };
layout(std430, binding = CSM_BIND_SLOT_CANDIDATES) readonly buffer SlotCandidates {
  uvec2 slotCandidates[];
};
layout(std430, binding = CSM_BIND_SLOT_COUNT) readonly buffer SlotCount { uint slotCount[]; };
layout(std430, binding = CSM_BIND_CANDIDATES) buffer Candidates { uvec2 candidates[]; };
layout(std430, binding = CSM_BIND_CANDIDATE_COUNT) buffer CandidateCount {
  uint candidateCount[];
};
layout(std430, binding = CSM_BIND_COUNTERS) buffer Counters { uint counters[]; };


void main() {
  uint a = globalIndex();
  if (a >= P.counts.x) return;
  uint here = P.grid.w * P.counts.x + a, before = (1u - P.grid.w) * P.counts.x + a;
  uint base = here * kList;
  uint n = 0u, dropped = 0u;
  // No slots when the grid did not fit this frame: no candidates.
  uint total = texelFetch(gridStartTex, int(P.grid.x + 1u)).x;
  if (total <= P.grid.y) {
    for (uint k = segBase[a]; k < segBase[a + 1u]; ++k) {
      uint m = slotCount[k];
      for (uint j = 0u; j < m; ++j) {
        uvec2 c = slotCandidates[k * uint(CSM_SLOT_CANDIDATES) + j];
        uint b = c.x & kIndex;
        if (n == kList) {
          ++dropped;  // this one or the highest listed
          if (b > (candidates[base + kList - 1u].x & kIndex)) continue;
        } else {
          ++n;
        }
        uint i = n - 1u;
        while (i > 0u && (candidates[base + i - 1u].x & kIndex) > b) {
          candidates[base + i] = candidates[base + i - 1u];
          --i;
        }
        candidates[base + i] = c;
      }
    }
  }
  candidateCount[here] = n;
  // Crossings: both lists are in ascending order.
  uint crossings = 0u;
  uint last = candidateCount[before], j = 0u;
  for (uint k = 0u; k < n; ++k) {
    uvec2 c = candidates[base + k];
    uint b = c.x & kIndex;
    if (b < a) continue;
    while (j < last && (candidates[before * kList + j].x & kIndex) < b) ++j;
    if (j < last && (candidates[before * kList + j].x & kIndex) == b &&
        crossed(candidates[before * kList + j].x >> uint(CSM_CANDIDATE_SHIFT),
                c.x >> uint(CSM_CANDIDATE_SHIFT)))
      ++crossings;
  }
  if (crossings > 0u) atomicAdd(counters[CSM_COUNTER_CROSSINGS], crossings);
  if (dropped > 0u) atomicAdd(counters[CSM_COUNTER_DROPPED], dropped);
}
