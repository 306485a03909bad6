// Strand contacts, pair scatter (counting sort of the candidate pairs by segment), one
// invocation per listed pair (an indirect dispatch, dispatch_size.comp): a stored pair (a, b)
// goes to both of its segments' ranges of PAIR_SIDES as each one's candidate (b with the
// pair's flags and contact distance into a's, a with them into b's; SEGMENT_BASE is the scan
// of the counts candidates.comp made). Counting each segment back down returns the counts to
// zero for the next frame. The order within a range depends on the schedule;
// candidate_lists.comp sorts it. A pair one of whose segments has more than
// CSM_MAX_CANDIDATES candidates is left out on both sides: its two slots get kNoCandidate.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(std430, binding = CSM_BIND_PAIR_LIST) readonly buffer PairList { uvec4 pairList[]; };
layout(std430, binding = CSM_BIND_SEGMENT_PAIRS) buffer SegmentPairs { uint segmentPairs[]; };
layout(std430, binding = CSM_BIND_SEGMENT_BASE) readonly buffer SegmentBase { uint segBase[]; };
layout(std430, binding = CSM_BIND_PAIR_SIDES) writeonly buffer PairSides { uvec2 pairSides[]; };
layout(std430, binding = CSM_BIND_COUNTERS) readonly buffer Counters { uint counters[]; };

void main() {
  uint k = globalIndex();
  if (k >= min(counters[CSM_COUNTER_PAIR_LIST], P.grid.z)) return;
  uvec4 p = pairList[k];
  uint a = p.x, b = p.y & kIndex, flags = p.y & ~kIndex;
  bool crowded =
      crowdedSides(segBase[a + 1u] - segBase[a]) || crowdedSides(segBase[b + 1u] - segBase[b]);
  pairSides[segBase[a] + atomicAdd(segmentPairs[a], 0xffffffffu) - 1u] =
      crowded ? uvec2(kNoCandidate) : p.yz;
  pairSides[segBase[b] + atomicAdd(segmentPairs[b], 0xffffffffu) - 1u] =
      crowded ? uvec2(kNoCandidate) : uvec2(a | flags, p.z);
}
