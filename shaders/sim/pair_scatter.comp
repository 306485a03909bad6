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

layout(binding = CSM_IMAGE_PAIR_LIST, rgba32ui) readonly uniform uimageBuffer pairList;
layout(std430, binding = CSM_BIND_SEGMENT_PAIRS) buffer SegmentPairs { uint segmentPairs[]; };
layout(std430, binding = CSM_BIND_SEGMENT_BASE) readonly buffer SegmentBase { uint segBase[]; };
layout(binding = CSM_IMAGE_PAIR_SIDES, rg32ui) writeonly uniform uimageBuffer pairSides;
#ifdef CSM_SPLIT_VIEWS
layout(binding = CSM_IMAGE_PAIR_SIDES_HIGH, rg32ui) writeonly uniform uimageBuffer pairSidesHigh;
uniform uint listSplit;  // the first slot of PAIR_SIDES_HIGH
#endif
layout(std430, binding = CSM_BIND_COUNTERS) readonly buffer Counters { uint counters[]; };

void storeSide(uint i, uvec2 c) {
#ifdef CSM_SPLIT_VIEWS
  if (i >= listSplit)
    imageStore(pairSidesHigh, int(i - listSplit), uvec4(c, 0u, 0u));
  else
#endif
    imageStore(pairSides, int(i), uvec4(c, 0u, 0u));
}

void main() {
  uint k = globalIndex();
  if (k >= min(counters[CSM_COUNTER_PAIR_LIST], P.pairListCapacity)) return;
  uvec4 p = imageLoad(pairList, int(k));
  uint a = p.x, b = p.y & kIndex, flags = p.y & ~kIndex;
  bool crowded =
      crowdedSides(segBase[a + 1u] - segBase[a]) || crowdedSides(segBase[b + 1u] - segBase[b]);
  uint sideA = segBase[a] + atomicAdd(segmentPairs[a], 0xffffffffu) - 1u;
  uint sideB = segBase[b] + atomicAdd(segmentPairs[b], 0xffffffffu) - 1u;
  storeSide(sideA, crowded ? uvec2(kNoCandidate) : p.yz);
  storeSide(sideB, crowded ? uvec2(kNoCandidate) : uvec2(a | flags, p.z));
}
