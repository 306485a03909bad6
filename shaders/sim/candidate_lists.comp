// Strand contacts, list pass (METHOD.md section 3.8), one invocation per segment: sorts the
// segment's candidates (pair_scatter.comp left them, with their flags and contact distances,
// in its range in no order) into its list, the same range of this frame's lists (CANDIDATES),
// in ascending order of the other segment; and counts crossings: pairs, from the lower
// segment's side, whose orientation flipped against the last list (LAST_CANDIDATES: last
// frame's, or the one before it within the frame with collision.lists; csm::findCandidates
// does the same on the CPU). Every candidate has its place: no list is cut short. A search
// whose grid or pair list did not fit keeps the lists before it. The sort is a heapsort: its
// loops take at most n (1 + 2 log2 n) iterations whatever the order the scatter left (an
// insertion sort takes up to n^2 / 2, past the 65,535 that llvmpipe allows an invocation at
// ~360 candidates: the lists of 30,000 strands of Fig. 1 came out cut short, differently from
// run to run). A segment over CSM_MAX_CANDIDATES lists
// nothing (pair_scatter.comp left its pairs out on both sides) and is counted as crowded, as
// is one whose loops still ended early.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(binding = CSM_TEX_GRID_START) uniform usamplerBuffer gridStartTex;

layout(std430, binding = CSM_BIND_SEGMENT_BASE) readonly buffer SegmentBase { uint segBase[]; };
layout(binding = CSM_IMAGE_PAIR_SIDES, rg32ui) readonly uniform uimageBuffer pairSides;
#define CSM_CANDIDATES_ACCESS  // written here
#include "sim/candidate_views.glsl"
layout(binding = CSM_IMAGE_LAST_CANDIDATES, rg32ui) readonly uniform uimageBuffer lastCandidates;
#ifdef CSM_SPLIT_VIEWS
layout(binding = CSM_IMAGE_PAIR_SIDES_HIGH, rg32ui) readonly uniform uimageBuffer pairSidesHigh;
layout(binding = CSM_IMAGE_LAST_CANDIDATES_HIGH, rg32ui) readonly uniform uimageBuffer
    lastCandidatesHigh;
#endif
layout(std430, binding = CSM_BIND_CANDIDATE_RANGE) buffer CandidateRange {
  uvec2 candidateRange[];
};
layout(std430, binding = CSM_BIND_COUNTERS) buffer Counters { uint counters[]; };
// The segments by candidate count (segment_order.comp): invocation i takes segment
// segmentOrder[i], so a SIMD group's lists are of like length.
layout(std430, binding = CSM_BIND_SEGMENT_ORDER) readonly buffer SegmentOrder {
  uint segmentOrder[];
};

uint keyOf(uvec2 c) { return c.x & kIndex; }
// Slot i of the sides, this frame's lists and last frame's, wherever its view is
// (candidateAt: candidate_views.glsl).
uvec2 sideAt(uint i) {
#ifdef CSM_SPLIT_VIEWS
  if (i >= listSplit) return imageLoad(pairSidesHigh, int(i - listSplit)).xy;
#endif
  return imageLoad(pairSides, int(i)).xy;
}
void setCandidate(uint i, uvec2 c) {
#ifdef CSM_SPLIT_VIEWS
  if (i >= listSplit)
    imageStore(candidatesHigh, int(i - listSplit), uvec4(c, 0u, 0u));
  else
#endif
    imageStore(candidates, int(i), uvec4(c, 0u, 0u));
}
uvec2 lastCandidateAt(uint i) {
#ifdef CSM_SPLIT_VIEWS
  if (i >= listSplit) return imageLoad(lastCandidatesHigh, int(i - listSplit)).xy;
#endif
  return imageLoad(lastCandidates, int(i)).xy;
}
uint lastOther(uint i) { return lastCandidateAt(i).x; }

// Max-heap on candidates[base, base + end): moves the candidate at `root` down to its place.
void siftDown(uint base, uint root, uint end) {
  uvec2 v = candidateAt(base + root);
  uint i = root;
  for (uint child = 2u * i + 1u; child < end; child = 2u * i + 1u) {
    uvec2 c = candidateAt(base + child);
    if (child + 1u < end) {
      uvec2 right = candidateAt(base + child + 1u);
      if (keyOf(right) > keyOf(c)) {
        c = right;
        ++child;
      }
    }
    if (keyOf(c) <= keyOf(v)) break;
    setCandidate(base + i, c);
    i = child;
  }
  setCandidate(base + i, v);
}

void main() {
  if (globalIndex() >= P.particles) return;
  uint a = segmentOrder[globalIndex()];
  uint here = P.listHalf * P.particles + a, before = (1u - P.listHalf) * P.particles + a;
  uint base = segBase[a];
  uint n = 0u;
  // When the grid or the pair list did not fit this search, the last list stays; the counters
  // say so (and keep the count of such searches).
  uint total = texelFetch(gridStartTex, int(P.bucketMask + 1u)).x;
  bool fits = total <= P.entryCapacity && counters[CSM_COUNTER_PAIR_LIST] <= P.pairListCapacity;
  if (a == 0u && !fits) ++counters[CSM_COUNTER_OVERFLOWS];
  uvec2 last = candidateRange[before];
  if (!fits) {
    // The last list stays (copied to the same slots of this one's storage, which is as
    // large): its pairs keep their sides and contact distances, and their constraints are
    // evaluated where the hair is now. Empty when there is none (the first list after a
    // reset or a growth of the pair list). No crossings are counted against it.
    for (uint k = 0u; k < last.y; ++k) setCandidate(last.x + k, lastCandidateAt(last.x + k));
    candidateRange[here] = last;
    return;
  }
  uint sides = segBase[a + 1u] - segBase[a];
  bool crowded = crowdedSides(sides);
  if (!crowded) {
    for (uint k = 0u; k < sides; ++k) {
      uvec2 c = sideAt(base + k);
      if (c.x != kNoCandidate) setCandidate(base + n++, c);
    }
    for (uint root = n / 2u; root > 0u; --root) siftDown(base, root - 1u, n);
    for (uint end = n; end > 1u; --end) {
      uvec2 top = candidateAt(base);
      setCandidate(base, candidateAt(base + end - 1u));
      setCandidate(base + end - 1u, top);
      siftDown(base, 0u, end - 1u);
    }
  }
  // Crossings: both lists are in ascending order.
  uint crossings = 0u, close = 0u;
  uint j = 0u, k = 0u, previous = 0u;
  bool sorted = true;
  for (; k < n; ++k) {
    uvec2 c = candidateAt(base + k);
    uint b = c.x & kIndex;
    if (k > 0u && b <= previous) sorted = false;
    previous = b;
    if (b < a) continue;
    uint other = 0u;
    for (; j < last.y; ++j) {
      other = lastOther(last.x + j);
      if ((other & kIndex) >= b) break;
    }
    if (j < last.y && (other & kIndex) == b &&
        crossed(other >> uint(CSM_CANDIDATE_SHIFT), c.x >> uint(CSM_CANDIDATE_SHIFT))) {
      ++crossings;
      if (uintBitsToFloat(c.y) < 2.0 * P.contactRadius) ++close;  // a rest distance
    }
  }
  // A list the driver's loop limit cut short: counted, and nothing listed.
  if (k < n || !sorted) {
    crowded = true;
    n = crossings = close = 0u;
  }
  candidateRange[here] = uvec2(base, n);
  if (crowded) atomicAdd(counters[CSM_COUNTER_CROWDED], 1u);
  if (crossings > 0u) atomicAdd(counters[CSM_COUNTER_CROSSINGS], crossings);
  if (close > 0u) atomicAdd(counters[CSM_COUNTER_CROSSINGS_CLOSE], close);
}
