// Strand contacts, candidate pass (METHOD.md section 3.3; the CPU reference is
// csm::findCandidates in sim/solver/contacts.cpp): the segment pairs closer than 2r + margin at the
// start of the frame, one invocation per grid entry (a segment in one of its cells), in grid
// order, so the invocations of a SIMD group usually share a bucket and read the same
// candidates (one cache line per gather). An entry tests only the entries after it in its
// bucket (each pair of a cell is met once, from its first entry), of the same cell (buckets
// can hold several), whose box overlaps its own in the cell, and that pass the same-strand
// gap rule; of those, a pair closer than the candidate distance whose closest points have
// their midpoint in this cell (the owner: a pair is kept in one cell only; see common.glsl)
// is measured (contacts,
// penetrations, the depth histogram: integer atomics, the same sums in any order) and
// appended to the pair list, lower segment first, with its flags and contact distance, and
// each of its segments counts it; pair_scatter.comp then gives every segment its pairs and
// candidate_lists.comp sorts them into its list. The list's order depends on the schedule,
// its content does not; a search whose pairs do not fit the list keeps the last list
// (candidate_lists.comp) and says so in the counters (CSM_COUNTER_PAIR_LIST over the
// capacity). Closest points: Ericson, Real-Time Collision Detection, 5.1.9; a pair is always evaluated lower segment first, as on
// the CPU, so that both agree on the candidate distance's boundary.
//
// Phases, because a SIMD lane that skips work still waits for the others (and on llvmpipe a
// branch is only a mask: both sides always run, and a loop body runs at least once), so rare
// work must not sit in the loop over candidates:
//  1. every candidate of a chunk of 128 entries, one texel each: the cell and the box
//     overlap (a bit per candidate that may touch);
//  2. the flagged ones: the gap rule, the closest points of the two segments and the owner
//     (a bit per pair within the candidate distance owned here);
//  3. the pairs within it: their closest points again (the same call on the same operands:
//     the same bits; cheaper than keeping s and t per candidate), their contact distance (2r,
//     or less where the groom put the two closer at rest: the rest positions are in the head
//     frame, which moves rigidly) and flags; measured and listed.
// Measured on Fig. 1 (llvmpipe): testing every entry of the bucket (and keeping the pairs
// whose other segment is higher) did twice the phase 1 work, a slab test of one segment
// against the other's box before the closest points cost more than it saved, and entries
// with the whole segment's box (owner: the lowest corner of the two boxes' overlap) had twice
// the candidates per entry and a fifth more overlaps than the boxes of the pieces in a cell.
// When the grid did not fit its buffers this frame (see grid_scatter.comp), no entry runs and
// every segment keeps its last list; the counters say so.
// An entry whose loops ended early (a cell so full that the driver's loop limit, 65,535
// iterations an invocation on llvmpipe, cut them short) is counted as crowded: it may have
// missed pairs.
#include "sim/common.glsl"

layout(local_size_x = CSM_CONTACT_GROUP) in;

#include "sim/particle_reads.glsl"
layout(binding = CSM_TEX_ENTRIES) uniform usamplerBuffer entryTex;
#ifdef CSM_STORAGE_READS
layout(std430, binding = CSM_BIND_GRID_START) readonly buffer GridStartIn { uint gridStartIn[]; };
#define readGridStart(i) gridStartIn[uint(i)]
#else
layout(binding = CSM_TEX_GRID_START) uniform usamplerBuffer gridStartTex;
#define readGridStart(i) texelFetch(gridStartTex, int(i)).x
#endif

layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_SEGMENT_PAIRS) buffer SegmentPairs { uint segmentPairs[]; };
layout(binding = CSM_IMAGE_PAIR_LIST, rgba32ui) writeonly uniform uimageBuffer pairList;
layout(std430, binding = CSM_BIND_COUNTERS) buffer Counters { uint counters[]; };

// 1: the frame's first list, whose pairs measure the state; 0: a list within the frame
// (collision.lists), listed but not measured.
uniform uint measured;

const uint kStrandGap = 2u;  // csm::kStrandGap: neighbours along one strand are not contacts
const uint kChunk = 128u;    // candidates per phase-1 bit mask (a uvec4)

shared uint groupContacts, groupPenetrations, groupCandidates;
shared uint groupDepth[CSM_DEPTH_BINS];

vec3 fetchPos(uint i) { return readPosition(i).xyz; }
vec3 fetchRest(uint i) { return readRest(i).xyz; }

// Index of the lowest set bit of a 128-bit mask (not zero), and clears it.
uint popLowest(inout uvec4 mask) {
  uint word = mask.x != 0u ? 0u : mask.y != 0u ? 1u : mask.z != 0u ? 2u : 3u;
  uint bit = uint(findLSB(mask[word]));
  mask[word] &= mask[word] - 1u;
  return 32u * word + bit;
}

// Segment a (at a0, a1) and segment `other`, the lower index first (p on it).
struct Pair {
  vec3 p0, p1, q0, q1;
};
Pair orderedPair(uint a, vec3 a0, vec3 a1, uint other) {
  vec3 o0 = fetchPos(other), o1 = fetchPos(other + 1u);
  // The operands are chosen before use: under a SIMD mask both sides of a branch run.
  bool lower = a < other;
  return Pair(lower ? a0 : o0, lower ? a1 : o1, lower ? o0 : a0, lower ? o1 : a1);
}

void main() {
  uint e = globalIndex();
  uint lid = gl_LocalInvocationID.x;
  if (lid == 0u) {
    groupContacts = 0u;
    groupPenetrations = 0u;
    groupCandidates = 0u;
  }
  if (lid < uint(CSM_DEPTH_BINS)) groupDepth[lid] = 0u;
  barrier();
  uint pairsHere = 0u, penetrationsHere = 0u, candidatesHere = 0u;
  float deepest = 0.0;
  bool cut = false;  // the loops ended early (the driver's loop limit)
  uint total = readGridStart(P.bucketMask + 1u);
  if (e < total && total <= P.entryCapacity) {
    uvec4 me = texelFetch(entryTex, int(e));
    uint key = me.x, a = me.y;
    uvec3 lowA = entryBoxLow(me), highA = entryBoxHigh(me);
    vec3 a0 = fetchPos(a), a1 = fetchPos(a + 1u);
    // Segments of a's own strand: [sFirst, sLast) (the gap rule).
    uint strandA = particleStrand[a];
    uint sFirst = strandFirst[strandA], sLast = strandFirst[strandA + 1u] - 1u;
    float r = P.contactRadius, twoR = 2.0 * r;
    float reach = P.candidateDistance;  // 2r + margin
    uint hi = readGridStart(bucketOf(key) + 1u);
    uint base = e + 1u;
    for (; base < hi; base += kChunk) {
      uint n = min(kChunk, hi - base);
      // Phase 1.
      uvec4 maybe = uvec4(0u);
      uint c = 0u;
      for (; c < n; ++c) {
        uvec4 cand = texelFetch(entryTex, int(base + c));
        if (cand.x == key && all(lessThanEqual(lowA, entryBoxHigh(cand))) &&
            all(lessThanEqual(entryBoxLow(cand), highA)))
          maybe[c >> 5u] |= 1u << (c & 31u);
      }
      if (c < n) cut = true;
      // Phase 2.
      uvec4 near = uvec4(0u);
      while (any(notEqual(maybe, uvec4(0u)))) {
        uint c = popLowest(maybe);
        uint other = texelFetch(entryTex, int(base + c)).y;
        uint low = min(a, other), high = max(a, other);
        if (low >= sFirst && high < sLast && high - low <= kStrandGap) continue;
        Pair pair = orderedPair(a, a0, a1, other);
        float s, t;
        float d2 = closestSegmentPoints(pair.p0, pair.p1, pair.q0, pair.q1, s, t);
        vec3 middle = 0.5 * (mix(pair.p0, pair.p1, s) + mix(pair.q0, pair.q1, t));
        if (d2 < reach * reach && cellKey(cellOf(middle)) == key)
          near[c >> 5u] |= 1u << (c & 31u);
      }
      if (any(notEqual(maybe, uvec4(0u)))) cut = true;
      // Phase 3.
      while (any(notEqual(near, uvec4(0u)))) {
        uint other = texelFetch(entryTex, int(base + popLowest(near))).y;
        uint low = min(a, other), high = max(a, other);
        Pair pair = orderedPair(a, a0, a1, other);
        float s, t;
        float dist = sqrt(closestSegmentPoints(pair.p0, pair.p1, pair.q0, pair.q1, s, t));
        float rs, rt;
        float d0 = min(twoR, sqrt(closestSegmentPoints(fetchRest(low), fetchRest(low + 1u),
                                                       fetchRest(high), fetchRest(high + 1u), rs,
                                                       rt)));
        uint flags = pairFlags(pair.p0, pair.p1, pair.q0, pair.q1, s, t, dist, twoR);
        ++candidatesHere;
        if (dist < twoR) ++pairsHere;
        if (dist < r) ++penetrationsHere;
        if (dist < d0) {
          float depth = (d0 - dist) / r;
          deepest = max(deepest, depth);
          atomicAdd(groupDepth[depthBin(depth)], 1u);
        }
        uint k = atomicAdd(counters[CSM_COUNTER_PAIR_LIST], 1u);
        if (k < P.pairListCapacity) {
          imageStore(pairList, int(k),
                     uvec4(low, high | (flags << uint(CSM_CANDIDATE_SHIFT)), floatBitsToUint(d0), 0u));
          atomicAdd(segmentPairs[low], 1u);
          atomicAdd(segmentPairs[high], 1u);
        }
      }
      if (any(notEqual(near, uvec4(0u)))) cut = true;
    }
    if (base < hi) cut = true;
  }
  if (cut) atomicAdd(counters[CSM_COUNTER_CROWDED], 1u);
  if (pairsHere > 0u) atomicAdd(groupContacts, pairsHere);
  if (penetrationsHere > 0u) atomicAdd(groupPenetrations, penetrationsHere);
  if (candidatesHere > 0u) atomicAdd(groupCandidates, candidatesHere);
  if (deepest > 0.0 && measured != 0u)
    atomicMax(counters[CSM_COUNTER_MAX_DEPTH], floatBitsToUint(deepest));
  barrier();
  if (measured == 0u) return;
  if (lid == 0u) {
    if (groupContacts > 0u) atomicAdd(counters[CSM_COUNTER_CONTACTS], groupContacts);
    if (groupPenetrations > 0u) atomicAdd(counters[CSM_COUNTER_PENETRATIONS], groupPenetrations);
    if (groupCandidates > 0u) atomicAdd(counters[CSM_COUNTER_CANDIDATES], groupCandidates);
  }
  if (lid < uint(CSM_DEPTH_BINS) && groupDepth[lid] > 0u)
    atomicAdd(counters[CSM_COUNTER_DEPTH + lid], groupDepth[lid]);
}
