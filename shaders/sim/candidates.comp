// Strand contacts, candidate pass (DESIGN.md section 1.7; the CPU reference is
// csm::findCandidates in sim/contacts.cpp): the segment pairs closer than 2r + margin at the
// start of the frame, one invocation per grid entry (a segment in one of its cells), in grid
// order, so the invocations of a SIMD group usually share a bucket and read the same
// candidates (one cache line per gather; a pass per segment over its own cells measured 1.9x
// slower on llvmpipe, its lanes reading different buckets). An entry tests a candidate only
// when the candidate is of the same cell (buckets can hold several), this cell holds the
// lowest corner of the overlap of the two padded boxes (the owner: a pair is met once from
// each side), the boxes overlap, and the pair passes the same-strand gap rule. It writes its
// pairs in ascending segment index into its slot (the segment's base + the cell's index in
// its box); candidate_lists.comp merges a segment's slots into its list. The scatter leaves
// each bucket in the order of its atomics, so the entry sorts its own pairs, which makes
// every list the same whatever the schedule (sorting an entry's few pairs costs far less than
// sorting the ~100 entries of each bucket). Closest points: Ericson, Real-Time Collision
// Detection, 5.1.9. From the lower segment's side it also measures the pair (contacts,
// penetrations, the depth histogram: integer atomics, the same sums in any order).
//
// Phases, because a SIMD lane that skips work still waits for the others (and on llvmpipe a
// branch is only a mask: both sides always run, and a loop body runs at least once), so rare
// work must not sit in the loop over candidates:
//  1. every candidate of a chunk of 128 entries, one texel each (entryLow): same cell, owner,
//     and half of the box overlap test (a bit per candidate that may touch);
//  2. the flagged ones (entryHigh): the other half of the overlap, the gap rule, and segment a
//     against b's box (a slab test);
//  3. the remaining ones: closest points of the two segments; pairs within the candidate
//     distance go into a list in shared memory sorted by segment index (a private array
//     indexed by a per-lane count measured 40% slower on llvmpipe);
//  4. the list: rest distance, flags and measures, into the slot. Should an entry have more
//     than kMaxContacts pairs, the list keeps the lowest indices and the scan runs again for
//     the next ones (rounds).
// When the grid did not fit its buffers this frame (see grid_scatter.comp), no entry runs and
// every segment's list is empty: the frame has no strand contacts, and the counters say so.
#include "sim/common.glsl"

layout(local_size_x = CSM_CONTACT_GROUP) in;

layout(binding = CSM_TEX_POSITION) uniform samplerBuffer posTex;
layout(binding = CSM_TEX_REST) uniform samplerBuffer restTex;
layout(binding = CSM_TEX_ENTRY_LOW) uniform usamplerBuffer entryLowTex;
layout(binding = CSM_TEX_ENTRY_HIGH) uniform usamplerBuffer entryHighTex;
layout(binding = CSM_TEX_GRID_START) uniform usamplerBuffer gridStartTex;

layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_SEGMENT_BASE) readonly buffer SegmentBase { uint segBase[]; };
layout(std430, binding = CSM_BIND_SLOT_CANDIDATES) writeonly buffer SlotCandidates {
  uvec2 slotCandidates[];
};
layout(std430, binding = CSM_BIND_SLOT_COUNT) writeonly buffer SlotCount { uint slotCount[]; };
layout(std430, binding = CSM_BIND_COUNTERS) buffer Counters { uint counters[]; };
layout(std430, binding = CSM_BIND_PAIRS) writeonly buffer Pairs { uvec2 pairs[]; };

const uint kStrandGap = 2u;     // csm::kStrandGap: neighbours along one strand are not contacts
const uint kChunk = 128u;       // candidates per phase-1 bit mask (a uvec4)
const uint kMaxContacts = 96u;  // pairs per round (Fig. 1: at most ~110 per segment)

shared uint groupContacts, groupPenetrations, groupCandidates, groupDropped;
shared uint groupDepth[CSM_DEPTH_BINS];
shared uint contactList[kMaxContacts * CSM_CONTACT_GROUP];  // [k * group size + lane], 24 KiB

vec3 fetchPos(uint i) { return texelFetch(posTex, int(i)).xyz; }

// Index of the lowest set bit of a 128-bit mask (not zero), and clears it.
uint popLowest(inout uvec4 mask) {
  uint word = mask.x != 0u ? 0u : mask.y != 0u ? 1u : mask.z != 0u ? 2u : 3u;
  uint bit = uint(findLSB(mask[word]));
  mask[word] &= mask[word] - 1u;
  return 32u * word + bit;
}

void main() {
  uint e = globalIndex();
  uint lid = gl_LocalInvocationID.x;
  if (lid == 0u) {
    groupContacts = 0u;
    groupPenetrations = 0u;
    groupCandidates = 0u;
    groupDropped = 0u;
  }
  if (lid < uint(CSM_DEPTH_BINS)) groupDepth[lid] = 0u;
  barrier();
  uint pairsHere = 0u, penetrationsHere = 0u, candidatesHere = 0u, droppedHere = 0u;
  float deepest = 0.0;
  uint total = texelFetch(gridStartTex, int(P.grid.x + 1u)).x;
  if (e < total && total <= P.grid.y) {
    uvec4 meLow = texelFetch(entryLowTex, int(e)), meHigh = texelFetch(entryHighTex, int(e));
    uint a = meHigh.w, key = meLow.w;
    // The box as the scatter computed it (segmentBox of the same positions).
    vec3 lowA = uintBitsToFloat(meLow.xyz), highA = uintBitsToFloat(meHigh.xyz);
    ivec3 cell = ivec3(uvec3(key, key >> 10u, key >> 20u) & 1023u) - 512;
    ivec3 boxLo = cellOf(lowA), span = cellOf(highA) - boxLo + 1;
    ivec3 d = cell - boxLo;
    uint slot = segBase[a] + uint((d.z * span.y + d.y) * span.x + d.x);
    vec3 a0 = fetchPos(a), a1 = fetchPos(a + 1u);
    // For the slab test of phase 2: axes along which a hardly moves are not tested (a
    // conservative pass; the box test covers them).
    bvec3 flatA = lessThan(abs(a1 - a0), vec3(1e-12));
    vec3 invA = 1.0 / mix(a1 - a0, vec3(1.0), flatA);
    // Segments of a's own strand: [sFirst, sLast) (the gap rule).
    uint strandA = particleStrand[a];
    uint sFirst = strandFirst[strandA], sLast = strandFirst[strandA + 1u] - 1u;
    float r = P.stepping.z;
    float twoR = 2.0 * r;
    float reach = P.contact.x;  // 2r + margin
    vec3 restA0 = texelFetch(restTex, int(a)).xyz, restA1 = texelFetch(restTex, int(a + 1u)).xyz;
    uint written = 0u;
    uint bucket = bucketOf(key);
    uint lo = texelFetch(gridStartTex, int(bucket)).x;
    uint hi = texelFetch(gridStartTex, int(bucket + 1u)).x;

    uint from = 0u;  // this round lists contacts with segments from this index on
    bool more = true;
    while (more) {
      more = false;
      uint listed = 0u;
      for (uint base = lo; base < hi; base += kChunk) {
        uint n = min(kChunk, hi - base);
        // Phase 1.
        uvec4 maybe = uvec4(0u);
        for (uint c = 0u; c < n; ++c) {
          uvec4 cand = texelFetch(entryLowTex, int(base + c));
          vec3 lowB = uintBitsToFloat(cand.xyz);
          if (cand.w == key && all(lessThanEqual(lowB, highA)) &&
              cellOf(max(lowA, lowB)) == cell)
            maybe[c >> 5u] |= 1u << (c & 31u);
        }
        // Phase 2.
        uvec4 close = uvec4(0u);
        while (any(notEqual(maybe, uvec4(0u)))) {
          uint c = popLowest(maybe);
          uvec4 cand = texelFetch(entryHighTex, int(base + c));
          uint b = cand.w;
          bool sameStrandNear =
              b >= sFirst && b < sLast && (b > a ? b - a : a - b) <= kStrandGap;
          vec3 highB = uintBitsToFloat(cand.xyz);
          // Segment a against b's box padded once more (2r in all, and slack): a point of
          // a within 2r of b lies in it, so a pair that misses it cannot touch (slab test;
          // on Fig. 1 it keeps 56 of the 87 candidates whose boxes overlap).
          vec3 lowB2 = uintBitsToFloat(texelFetch(entryLowTex, int(base + c)).xyz) - P.cells.z;
          vec3 t0 = (lowB2 - a0) * invA, t1 = (highB + P.cells.z - a0) * invA;
          vec3 tNear = mix(min(t0, t1), vec3(-1e30), flatA);
          vec3 tFar = mix(max(t0, t1), vec3(1e30), flatA);
          bool crosses = max(max(tNear.x, tNear.y), max(tNear.z, 0.0)) <=
                         min(min(tFar.x, tFar.y), min(tFar.z, 1.0));
          if (b != a && b >= from && !sameStrandNear && all(lessThanEqual(lowA, highB)) &&
              crosses)
            close[c >> 5u] |= 1u << (c & 31u);
        }
        // Phase 3.
        while (any(notEqual(close, uvec4(0u)))) {
          uint b = texelFetch(entryHighTex, int(base + popLowest(close))).w;
          vec3 b0 = fetchPos(b), b1 = fetchPos(b + 1u);
          // The pair as CpuSolver sees it, lower index first. The operands are chosen
          // before the call: under a SIMD mask both sides of a ?: would run it.
          bool lower = a < b;
          float s, t;
          float d2 = closestSegmentPoints(lower ? a0 : b0, lower ? a1 : b1,
                                          lower ? b0 : a0, lower ? b1 : a1, s, t);
          if (d2 >= reach * reach) continue;
          // Into the sorted list; when it is full, the highest index waits for the
          // next round.
          uint last = (kMaxContacts - 1u) * CSM_CONTACT_GROUP + lid;
          if (listed == kMaxContacts) {
            more = true;
            if (b > contactList[last]) continue;
          } else {
            ++listed;
          }
          uint k = listed - 1u;
          while (k > 0u && contactList[(k - 1u) * CSM_CONTACT_GROUP + lid] > b) {
            contactList[k * CSM_CONTACT_GROUP + lid] =
                contactList[(k - 1u) * CSM_CONTACT_GROUP + lid];
            --k;
          }
          contactList[k * CSM_CONTACT_GROUP + lid] = b;
        }
      }
      // Phase 4, in ascending b: the same order whatever the order of the buckets.
      for (uint k = 0u; k < listed; ++k) {
        uint b = contactList[k * CSM_CONTACT_GROUP + lid];
        vec3 b0 = fetchPos(b), b1 = fetchPos(b + 1u);
        // The pair as CpuSolver sees it: lower index first (s on it, t on the other).
        bool lower = a < b;
        vec3 p0 = lower ? a0 : b0, p1 = lower ? a1 : b1;
        vec3 q0 = lower ? b0 : a0, q1 = lower ? b1 : a1;
        float s, t;
        float dist = sqrt(closestSegmentPoints(p0, p1, q0, q1, s, t));
        // Pairs the groom put closer than 2r keep their rest distance (the rest positions
        // are in the head frame, which moves rigidly).
        vec3 rb0 = texelFetch(restTex, int(b)).xyz, rb1 = texelFetch(restTex, int(b + 1u)).xyz;
        float rs, rt;
        float restD = sqrt(closestSegmentPoints(lower ? restA0 : rb0, lower ? restA1 : rb1,
                                                lower ? rb0 : restA0, lower ? rb1 : restA1, rs,
                                                rt));
        float d0 = min(twoR, restD);
        uint flags = pairFlags(p0, p1, q0, q1, s, t, dist, twoR);
        if (written < uint(CSM_SLOT_CANDIDATES)) {
          slotCandidates[slot * uint(CSM_SLOT_CANDIDATES) + written] =
              uvec2(b | (flags << uint(CSM_CANDIDATE_SHIFT)), floatBitsToUint(d0));
          ++written;
        } else {
          ++droppedHere;
        }
        if (lower) {
          ++candidatesHere;
          if (dist < twoR) ++pairsHere;
          if (dist < d0) {
            float depth = (d0 - dist) / r;
            deepest = max(deepest, depth);
            atomicAdd(groupDepth[depthBin(depth)], 1u);
          }
          if (dist < r) ++penetrationsHere;
          if (P.counts.w > 0u && dist < twoR) {
            uint pairSlot = atomicAdd(counters[CSM_COUNTER_PAIRS], 1u);
            if (pairSlot < P.counts.w) pairs[pairSlot] = uvec2(a, b);
          }
        }
      }
      if (more) from = contactList[(kMaxContacts - 1u) * CSM_CONTACT_GROUP + lid] + 1u;
    }
    slotCount[slot] = written;
  }
  if (pairsHere > 0u) atomicAdd(groupContacts, pairsHere);
  if (penetrationsHere > 0u) atomicAdd(groupPenetrations, penetrationsHere);
  if (candidatesHere > 0u) atomicAdd(groupCandidates, candidatesHere);
  if (droppedHere > 0u) atomicAdd(groupDropped, droppedHere);
  if (deepest > 0.0) atomicMax(counters[CSM_COUNTER_MAX_DEPTH], floatBitsToUint(deepest));
  barrier();
  if (lid == 0u) {
    if (groupContacts > 0u) atomicAdd(counters[CSM_COUNTER_CONTACTS], groupContacts);
    if (groupPenetrations > 0u) atomicAdd(counters[CSM_COUNTER_PENETRATIONS], groupPenetrations);
    if (groupCandidates > 0u) atomicAdd(counters[CSM_COUNTER_CANDIDATES], groupCandidates);
    if (groupDropped > 0u) atomicAdd(counters[CSM_COUNTER_DROPPED], groupDropped);
  }
  if (lid < uint(CSM_DEPTH_BINS) && groupDepth[lid] > 0u)
    atomicAdd(counters[CSM_COUNTER_DEPTH + lid], groupDepth[lid]);
}
