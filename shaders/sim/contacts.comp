// Collision pass, contacts (DESIGN.md section 1 step 7, paper section 3.3): one invocation
// per grid entry, in grid order, so the invocations of a SIMD group usually share a cell and
// walk the same candidates. Each segment visits the 27 cells around its own (9 runs of 3
// buckets; distinct buckets, see bucketOf), cut along x to the window it can reach (buckets
// are sorted by x: a binary search in the first and last bucket of a run saves a third of
// the candidates), tests every candidate, and sums the penalty, normal damping and
// Coulomb-limited friction of all its contacts into its own slot: every pair is met from
// both sides, and both sides evaluate it with the lower segment index first, so the two
// forces are exact opposites. No float atomics: the slot is written once, and the candidates
// come in a fixed order (runs by offset; within a bucket by x, then segment index), so the
// sums are deterministic whatever the schedule. The particles gather from their segments'
// slots in predict.comp. Formulas: CpuSolver::collide. Closest points: Ericson, Real-Time
// Collision Detection, 5.1.9.
//
// Three phases, because a SIMD lane that skips work still waits for the others (and on
// llvmpipe a branch is only a mask: both sides always run, and a loop body runs at least
// once), so rare work must not sit in the loop over candidates:
//  1. every candidate of a chunk of 128: a cheap, conservative test of its midpoint against
//     this segment (a bit per candidate that may touch);
//  2. the chunk's flagged candidates: closest points of the two segments, contacts as bits,
//     then appended to a per-invocation list in shared memory (a private array indexed by a
//     per-lane count measured 40% slower on llvmpipe);
//  3. the list: forces. Should a segment have more than kMaxContacts contacts, the scan
//     runs again for the next ones (rounds), keeping the order.
#include "sim/common.glsl"

layout(local_size_x = CSM_CONTACT_GROUP) in;

layout(binding = CSM_TEX_POSITION) uniform samplerBuffer posTex;
layout(binding = CSM_TEX_VELOCITY) uniform samplerBuffer velTex;
layout(binding = CSM_TEX_REST) uniform samplerBuffer restTex;
layout(binding = CSM_TEX_SORTED_DATA) uniform samplerBuffer sortedTex;
layout(binding = CSM_TEX_GRID_START) uniform usamplerBuffer gridStartTex;

layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_SEGMENT_FORCE) writeonly buffer SegmentForce { vec4 segForce[]; };
layout(std430, binding = CSM_BIND_SEGMENT_CONTACTS) writeonly buffer SegmentContacts {
  uint segContacts[];
};
layout(std430, binding = CSM_BIND_COUNTERS) buffer Counters { uint counters[]; };
layout(std430, binding = CSM_BIND_PAIRS) writeonly buffer Pairs { uvec2 pairs[]; };

const uint kStrandGap = 2u;     // csm::kStrandGap: neighbours along one strand are not contacts
const uint kChunk = 128u;       // candidates per phase-1 bit mask (a uvec4)
const uint kMaxContacts = 96u;  // contacts per round (Fig. 1: at most ~110 per segment)

shared uint groupContacts, groupPenetrations;
shared uint contactList[kMaxContacts * CSM_CONTACT_GROUP];  // [k * group size + lane], 24 KiB

vec3 fetchPos(uint i) { return texelFetch(posTex, int(i)).xyz; }

// The first entry of [lo, hi) whose midpoint x is not below x.
uint lowerBoundX(uint lo, uint hi, float x) {
  while (lo < hi) {
    uint mid = (lo + hi) >> 1u;
    if (texelFetch(sortedTex, int(mid)).x < x) lo = mid + 1u;
    else hi = mid;
  }
  return lo;
}

void main() {
  uint j = globalIndex();
  uint lid = gl_LocalInvocationID.x;
  if (lid == 0u) {
    groupContacts = 0u;
    groupPenetrations = 0u;
  }
  barrier();
  uint pairsHere = 0u, penetrationsHere = 0u;
  if (j < P.counts.z) {
    vec4 me = texelFetch(sortedTex, int(j));
    uint a = decodeIndex(me.w);
    // Segments of a's own strand: [sFirst, sLast) (the gap rule).
    uint strandA = particleStrand[a];
    uint sFirst = strandFirst[strandA], sLast = strandFirst[strandA + 1u] - 1u;
    vec3 a0 = fetchPos(a), a1 = fetchPos(a + 1u);
    vec3 ad = a1 - a0;
    float add = dot(ad, ad);
    float invAdd = add > 0.0 ? 1.0 / add : 0.0;
    float longest = uintBitsToFloat(counters[CSM_COUNTER_LONGEST]);
    float r = P.stepping.z;
    float twoR = 2.0 * r;
    float stiffness = P.contact.x, damping = P.contact.y, friction = P.contact.z;
    float dt = P.contact.w;
    float massA = 0.5 * (texelFetch(restTex, int(a)).w + texelFetch(restTex, int(a + 1u)).w);
    // Phase-1 bound: a segment b within 2r of a has its midpoint within 2r + |b|/2 of a, and
    // |b| <= the longest segment. The slack covers rounding.
    float reach = (0.5 * longest + twoR) * P.misc.w + 1e-7;
    float reach2 = reach * reach;
    // Candidates' midpoints lie within reach of a's segment, so within reach + |a|/2 of its
    // midpoint along x.
    float window = reach + 0.5 * sqrt(add) * P.misc.w + 1e-7;
    uint home = bucketOf(cellOf(me.xyz, cellSize(floatBitsToUint(longest))));
    uint buckets = P.grid.x + 1u;

    vec3 f0 = vec3(0.0), f1 = vec3(0.0);
    uint count = 0u;
    uint skip = 0u;  // contacts handled by earlier rounds
    bool more = true;
    while (more) {
      more = false;
      uint seen = 0u, listed = 0u;
      for (int run = 0; run < 9; ++run) {
        // Buckets first, first+1, first+2 hold the cells at dx = -1, 0, +1: one range of
        // entries, cut to the window by binary search in the outer two, unless the run wraps
        // around the end of the table (then three).
        uint first = (home + P.runs[run >> 2][run & 3] - 1u) & P.grid.x;
        uint pieces = first + 3u <= buckets ? 1u : 3u;
        for (uint piece = 0u; piece < pieces; ++piece) {
          uint b0 = (first + piece) & P.grid.x;
          uint b1 = pieces == 1u ? first + 2u : b0;
          uint lo = texelFetch(gridStartTex, int(b0)).x;
          uint hi = texelFetch(gridStartTex, int(b1 + 1u)).x;
          if (piece == 0u) lo = lowerBoundX(lo, texelFetch(gridStartTex, int(b0 + 1u)).x, me.x - window);
          if (piece + 1u == pieces)
            hi = lowerBoundX(texelFetch(gridStartTex, int(b1)).x, hi, me.x + window);
          for (uint base = lo; base < hi; base += kChunk) {
            uint n = min(kChunk, hi - base);
            // Phase 1: a bit per candidate that may touch.
            uvec4 maybe = uvec4(0u);
            for (uint c = 0u; c < n; ++c) {
              vec3 m = texelFetch(sortedTex, int(base + c)).xyz;
              float t = clamp(dot(m - a0, ad) * invAdd, 0.0, 1.0);
              vec3 off = a0 + t * ad - m;
              if (dot(off, off) < reach2) maybe[c >> 5u] |= 1u << (c & 31u);
            }
            // Phase 2: closest points of the flagged ones; contacts as bits again.
            uvec4 touching = uvec4(0u);
            while (any(notEqual(maybe, uvec4(0u)))) {
              uint word = maybe.x != 0u ? 0u : maybe.y != 0u ? 1u : maybe.z != 0u ? 2u : 3u;
              uint bit = uint(findLSB(maybe[word]));
              maybe[word] &= maybe[word] - 1u;
              uint b = decodeIndex(texelFetch(sortedTex, int(base + 32u * word + bit)).w);
              bool sameStrandNear =
                  b >= sFirst && b < sLast && (b > a ? b - a : a - b) <= kStrandGap;
              vec3 b0 = fetchPos(b), b1 = fetchPos(b + 1u);
              // The pair as CpuSolver sees it, lower index first. The operands are chosen
              // before the call: under a SIMD mask both sides of a ?: would run it.
              bool lower = a < b;
              float s, t;
              float d2 = closestSegmentPoints(lower ? a0 : b0, lower ? a1 : b1, lower ? b0 : a0,
                                              lower ? b1 : a1, s, t);
              if (b != a && !sameStrandNear && d2 < twoR * twoR) touching[word] |= 1u << bit;
            }
            // The chunk's contacts, in candidate order, to the list (rounds: see above).
            while (any(notEqual(touching, uvec4(0u)))) {
              uint word = touching.x != 0u ? 0u : touching.y != 0u ? 1u : touching.z != 0u ? 2u : 3u;
              uint bit = uint(findLSB(touching[word]));
              touching[word] &= touching[word] - 1u;
              if (seen >= skip) {
                if (listed < kMaxContacts)
                  contactList[(listed++) * CSM_CONTACT_GROUP + lid] =
                      decodeIndex(texelFetch(sortedTex, int(base + 32u * word + bit)).w);
                else
                  more = true;
              }
              ++seen;
            }
          }
        }
      }
      // Phase 3.
      for (uint k = 0u; k < listed; ++k) {
        uint b = contactList[k * CSM_CONTACT_GROUP + lid];
        vec3 b0 = fetchPos(b), b1 = fetchPos(b + 1u);
        // The pair as CpuSolver sees it: lower index first (s on it, t on the other).
        bool lower = a < b;
        vec3 p0 = lower ? a0 : b0, p1 = lower ? a1 : b1;
        vec3 q0 = lower ? b0 : a0, q1 = lower ? b1 : a1;
        uint pl = lower ? a : b, ql = lower ? b : a;
        float s, t;
        float dist = sqrt(closestSegmentPoints(p0, p1, q0, q1, s, t));
        vec3 nrm = mix(p0, p1, s) - mix(q0, q1, t);
        if (dist > 1e-12) {
          nrm /= dist;
        } else {
          // Crossing exactly: push apart across both directions.
          nrm = cross(p1 - p0, q1 - q0);
          float len = length(nrm);
          nrm = len > 1e-15 ? nrm / len : vec3(0.0, 1.0, 0.0);
        }
        vec3 vp = mix(texelFetch(velTex, int(pl)).xyz, texelFetch(velTex, int(pl + 1u)).xyz, s);
        vec3 vq = mix(texelFetch(velTex, int(ql)).xyz, texelFetch(velTex, int(ql + 1u)).xyz, t);
        vec3 rel = vp - vq;
        float vn = dot(rel, nrm);
        float an = max(0.0, stiffness * (twoR - dist) - damping * vn);
        vec3 vt = rel - vn * nrm;
        float vtLen = length(vt);
        vec3 acc = an * nrm;
        if (vtLen > 1e-12) acc -= min(friction * an, vtLen / dt) * (vt / vtLen);
        float massB = 0.5 * (texelFetch(restTex, int(b)).w + texelFetch(restTex, int(b + 1u)).w);
        vec3 f = 0.5 * ((lower ? massA : massB) + (lower ? massB : massA)) * acc;
        if (lower) {
          f0 += (1.0 - s) * f;
          f1 += s * f;
          ++pairsHere;
          if (dist < r) ++penetrationsHere;
          if (P.counts.w > 0u) {
            uint slot = atomicAdd(counters[CSM_COUNTER_PAIRS], 1u);
            if (slot < P.counts.w) pairs[slot] = uvec2(a, b);
          }
        } else {
          f0 -= (1.0 - t) * f;
          f1 -= t * f;
        }
        ++count;
      }
      skip += kMaxContacts;
    }
    segForce[2u * a] = vec4(f0, 0.0);
    segForce[2u * a + 1u] = vec4(f1, 0.0);
    segContacts[a] = count;
  }
  if (pairsHere > 0u) atomicAdd(groupContacts, pairsHere);
  if (penetrationsHere > 0u) atomicAdd(groupPenetrations, penetrationsHere);
  barrier();
  if (lid == 0u) {
    if (groupContacts > 0u) atomicAdd(counters[CSM_COUNTER_CONTACTS], groupContacts);
    if (groupPenetrations > 0u) atomicAdd(counters[CSM_COUNTER_PENETRATIONS], groupPenetrations);
  }
}
