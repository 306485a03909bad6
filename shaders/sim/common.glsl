// Shared by every pass of the GPU solver: binding points, the parameter block, indexing,
// quaternions, closest points of segments and the hash grid.
// The C++ side of SimParams and Substep is csm::gpu::SimParams / Substep in
// sim/gpu/gpu_params.h; a test compares the two layouts through GL's program introspection.
#include "sim/bindings.glsl"
#include "sim/shared_constants.glsl"
#include "sim/shared_functions.glsl"

// The parameter block, declared once for C++ and GLSL (shaders/sim/shared_constants.glsl says
// what each field holds).
struct SimParams {
  CSM_SIM_PARAMS(CSM_MEMBER)
};

struct Substep {
  CSM_SUBSTEP(CSM_MEMBER)
};

#ifdef CSM_PARAMS_UNIFORM
// std140 lays these structs out as std430 does (no arrays of scalars in them, every struct a
// multiple of 16 bytes); the buffer is allocated whole (GpuSolver::writeParams).
layout(std140, binding = CSM_UNIFORM_PARAMS) uniform Params {
  SimParams P;
  Substep S[CSM_MAX_SUBSTEPS];
};
#else
layout(std430, binding = CSM_BIND_PARAMS) readonly buffer Params {
  SimParams P;
  Substep S[];
};
#endif

// Items beyond 65535 work groups are dispatched as a 2D grid of groups (the GL 4.3 minimum
// for gl_NumWorkGroups.x); this flattens it back. A macro: gl_WorkGroupSize exists only
// after the pass declares its local size, below this include.
#define globalIndex()                                                                \
  ((gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + \
   gl_LocalInvocationID.x)

// A strand's held particles, from its CSM_BIND_STRAND_STIFFNESS entry (shared_constants.glsl,
// CSM_TIP_HELD): the pinned ones from the root, and whether the head holds its tip too.
int pinnedOf(vec4 stiff) { return int(stiff.z) % CSM_TIP_HELD; }
bool tipHeldOf(vec4 stiff) { return int(stiff.z) >= CSM_TIP_HELD; }
// Whether the head holds particle j of a strand of n (csm::Regions::held).
bool heldAt(vec4 stiff, int j, int n) {
  return j < pinnedOf(stiff) || (tipHeldOf(stiff) && j == n - 1);
}

// --- Quaternions as vec4(x, y, z, w), Hamilton products, like Eigen::Quaternion. ---

vec4 quatMul(vec4 a, vec4 b) {
  return vec4(a.w * b.xyz + b.w * a.xyz + cross(a.xyz, b.xyz), a.w * b.w - dot(a.xyz, b.xyz));
}

// v turned by the unit quaternion q (xyz, w), and by its inverse.
vec3 quatTurn(vec4 q, vec3 v) {
  vec3 t = 2.0 * cross(q.xyz, v);
  return v + q.w * t + cross(q.xyz, t);
}
vec3 quatUnturn(vec4 q, vec3 v) {
  return quatTurn(vec4(-q.xyz, q.w), v);
}

// Eigen's QuaternionBase::toRotationMatrix, term for term (columns here).
mat3 quatToMat(vec4 q) {
  float tx = 2.0 * q.x, ty = 2.0 * q.y, tz = 2.0 * q.z;
  float twx = tx * q.w, twy = ty * q.w, twz = tz * q.w;
  float txx = tx * q.x, txy = ty * q.x, txz = tz * q.x;
  float tyy = ty * q.y, tyz = tz * q.y, tzz = tz * q.z;
  return mat3(vec3(1.0 - (tyy + tzz), txy + twz, txz - twy),
              vec3(txy - twz, 1.0 - (txx + tzz), tyz + twx),
              vec3(txz + twy, tyz - twx, 1.0 - (txx + tyy)));
}

// Rotational part of A (Mueller, Bender, Chentanez, Macklin 2016, "A Robust Method to Extract
// the Rotational Part of Deformations"), warm-started from last step's q: each iteration turns
// R's columns toward A's by the torque they make over the region's rest moment J (1 / J is
// invJ; 0 leaves q alone), the value of sum r.a at convergence: scale-free. Robust when A is
// rank-deficient (straight strands). The turn about the rest-frame `axis` (unit, or zero) is
// taken at twistStep of its size (see csm::extractRotation). Same arithmetic, in float.
vec4 extractRotation(mat3 A, float invJ, vec4 q, int iterations, vec3 axis, float twistStep) {
  // A non-finite stored rotation starts again from none; a non-finite A leaves q as it is
  // (the warm start would otherwise keep a NaN for good).
  if (any(isnan(q)) || any(isinf(q))) q = vec4(0.0, 0.0, 0.0, 1.0);
  for (int it = 0; it < iterations; ++it) {
    mat3 R = quatToMat(q);
    vec3 omega = (cross(R[0], A[0]) + cross(R[1], A[1]) + cross(R[2], A[2])) * invJ;
    vec3 e = R * axis;
    omega -= (1.0 - twistStep) * dot(omega, e) * e;
    float angle = length(omega);
    if (isnan(angle) || isinf(angle) || angle < 1e-12) break;
    float half_ = 0.5 * angle;
    q = quatMul(vec4(sin(half_) * (omega / angle), cos(half_)), q);
    q = q / length(q);
  }
  return q;
}

// --- Hair-hair collision. ---

// Closest points of segments p0-p1 and q0-q1 (Ericson, Real-Time Collision Detection,
// section 5.1.9), as csm::closestSegmentPoints (sim/core/segment_pairs.cpp). Returns the squared
// distance.
float closestSegmentPoints(vec3 p0, vec3 p1, vec3 q0, vec3 q1, out float s, out float t) {
  vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  float a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  const float eps = 1e-20;
  if (a <= eps && e <= eps) {
    s = 0.0;
    t = 0.0;
  } else if (a <= eps) {
    s = 0.0;
    t = clamp(f / e, 0.0, 1.0);
  } else {
    float c = dot(d1, r);
    if (e <= eps) {
      t = 0.0;
      s = clamp(-c / a, 0.0, 1.0);
    } else {
      float b = dot(d1, d2);
      float denom = a * e - b * b;
      s = denom > eps * a * e ? clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  vec3 diff = (p0 + d1 * s) - (q0 + d2 * t);
  return dot(diff, diff);
}

// Strand contacts (sim/solver/contacts.h): the histogram bin of a penetration depth (in r), and the
// orientation flags of a pair (csm::pairFlags): closest points inside both segments, closer
// than 2r, sign of the triple product, skew enough for that sign to say which side.
int depthBin(float depthInR) {
  return clamp(int(depthInR * float(CSM_DEPTH_BINS_PER_R)), 0, CSM_DEPTH_BINS - 1);
}

const uint kPairInterior = CSM_PAIR_INTERIOR, kPairNear = CSM_PAIR_NEAR,
           kPairPositive = CSM_PAIR_POSITIVE, kPairSkew = CSM_PAIR_SKEW;
const float kSkewSine = CSM_SKEW_SINE;
const float kInside = CSM_PAIR_INSIDE;

bool interior(float s, float t) {
  return s > kInside && s < 1.0 - kInside && t > kInside && t < 1.0 - kInside;
}

// Whether segments along a and b, their cross product n, are skew enough to have a side.
bool skew(vec3 n, vec3 a, vec3 b) { return length(n) > kSkewSine * length(a) * length(b); }

uint pairFlags(vec3 a0, vec3 a1, vec3 b0, vec3 b1, float s, float t, float dist, float twoR) {
  uint f = 0u;
  if (interior(s, t)) f |= kPairInterior;
  if (dist < twoR) f |= kPairNear;
  vec3 n = cross(a1 - a0, b1 - b0);
  if (dot(n, a0 - b0) > 0.0) f |= kPairPositive;
  if (skew(n, a1 - a0, b1 - b0)) f |= kPairSkew;
  return f;
}

// csm::keptSide and csm::contactNormal: the side a listed pair keeps (+1, -1, or 0 for none),
// and the direction a contact pushes p (the lower segment) with the separation along it.
float keptSide(uint flags) {
  if ((flags & (kPairInterior | kPairSkew)) != (kPairInterior | kPairSkew)) return 0.0;
  return (flags & kPairPositive) != 0u ? 1.0 : -1.0;
}

vec3 contactNormal(vec3 p0, vec3 p1, vec3 q0, vec3 q1, float s, float t, float d, float side,
                   out float separation) {
  vec3 between = mix(p0, p1, s) - mix(q0, q1, t);
  if (side != 0.0 && interior(s, t)) {
    vec3 n = cross(p1 - p0, q1 - q0);
    if (skew(n, p1 - p0, q1 - q0)) {
      vec3 nrm = (side / length(n)) * n;
      separation = dot(between, nrm);
      return nrm;
    }
  }
  separation = d;
  if (d > 1e-12) return between / d;
  vec3 n = cross(p1 - p0, q1 - q0);
  float len = length(n);
  return len > 1e-15 ? n / len : vec3(0.0, 1.0, 0.0);
}

// A candidate list entry (CSM_IMAGE_CANDIDATES): the other segment in the low bits, the
// pair's flags above them.
const uint kIndex = (1u << uint(CSM_CANDIDATE_SHIFT)) - 1u;
// A slot of PAIR_SIDES whose pair was left out (pair_scatter.comp): no candidate.
const uint kNoCandidate = 0xffffffffu;
// Whether a segment with `sides` candidates (its range in PAIR_SIDES) is over the cap: the
// pair scatter leaves its pairs out and the list pass counts it, by this one rule.
bool crowdedSides(uint sides) { return sides > uint(CSM_MAX_CANDIDATES); }

bool crossed(uint before, uint now) {
  return (before & now & kPairInterior) != 0u && ((before | now) & kPairNear) != 0u &&
         ((before ^ now) & kPairPositive) != 0u;
}

// The collision grid (METHOD.md section 3.6): cells of edge P.cellEdge, at least twice the
// contact distance and half or three quarters of a mean segment (ContactSearch::cellSize:
// half in dense hair). Each segment is entered in every cell that its capsule of radius
// P.cellPadding (half the candidate distance and 1% for rounding) reaches: the cells of its
// padded box that the segment itself passes within P.cellPadding of (clipToCell), with the box of
// the part it has there. A pair is kept only in the cell holding the midpoint of its closest
// points (the owner): both segments lie within half the candidate distance of that point, so
// both are entered there and their boxes there overlap, and the pair is found
// exactly once. Every pass computes cells, clips and boxes with these functions from the same
// positions, so they agree to the bit.

// Cells are counted from the head (P.gridOrigin) and clamped to -512..511 per axis (+-6.7 m with
// Fig. 1's 13 mm cells): a cell's 30-bit key is then exact, and a far-away segment of an
// exploding simulation shares the border cells instead of overflowing (slower, still exact:
// a border cell takes the whole segment, and the owner of a pair out there is a border cell).
const int kCellLow = -512, kCellHigh = 511;  // the clamp; 10 bits of a key per axis
ivec3 cellOf(vec3 p) {
  return ivec3(clamp(floor((p - P.gridOrigin) * P.inverseCellEdge), float(kCellLow), float(kCellHigh)));
}

// inMeasureSample(s, stride): shared_functions.glsl, the same text the C++ compiles.

uint cellKey(ivec3 c) {
  uvec3 u = uvec3(c - kCellLow);
  return u.x | (u.y << 10u) | (u.z << 20u);
}

void segmentBox(vec3 p0, vec3 p1, out vec3 lo, out vec3 hi) {
  lo = min(p0, p1) - P.cellPadding;
  hi = max(p0, p1) + P.cellPadding;
}

// The part of segment p0-p1 within cell c grown by P.cellPadding on every side, [q0, q1]: false
// when the segment misses it (the cell is in its padded box, but the segment passes farther
// than P.cellPadding from it). A border cell (see cellOf) takes the whole segment. `precise`: the
// count and scatter passes must agree on every cell to the bit (each bucket's count returns
// to zero), so no compiler may fuse or reorder this arithmetic differently in the two.
bool clipToCell(vec3 p0, vec3 p1, ivec3 c, out vec3 q0, out vec3 q1) {
  q0 = p0;
  q1 = p1;
  if (any(equal(c, ivec3(kCellLow))) || any(equal(c, ivec3(kCellHigh)))) return true;
  precise vec3 lo = P.gridOrigin + vec3(c) * P.cellEdge - P.cellPadding;
  precise vec3 hi = lo + vec3(P.cellEdge + 2.0 * P.cellPadding);
  precise vec3 d = p1 - p0;
  // Axes along which the segment hardly moves do not clip: the padded box put it in range.
  bvec3 still = lessThan(abs(d), vec3(1e-12));
  precise vec3 inv = 1.0 / mix(d, vec3(1.0), still);
  precise vec3 ta = (lo - p0) * inv, tb = (hi - p0) * inv;
  vec3 tNear = mix(min(ta, tb), vec3(-1e30), still), tFar = mix(max(ta, tb), vec3(1e30), still);
  float t0 = max(max(tNear.x, tNear.y), max(tNear.z, 0.0));
  float t1 = min(min(tFar.x, tFar.y), min(tFar.z, 1.0));
  q0 = p0 + d * t0;
  q1 = p0 + d * t1;
  return t0 <= t1;
}

// A grid entry in one texel (CSM_IMAGE_ENTRIES): the cell's key, the segment, and the part of
// the box of its piece in the cell (padded) that lies inside the cell, in 1023 steps per axis,
// rounded outward (two boxes that overlap in the cell overlap here too).
const float kEntrySteps = 1023.0;
uvec4 packEntry(uint key, uint segment, vec3 low, vec3 high, ivec3 cell) {
  vec3 l = (low - P.gridOrigin) * P.inverseCellEdge - vec3(cell);
  vec3 h = (high - P.gridOrigin) * P.inverseCellEdge - vec3(cell);
  uvec3 ql = uvec3(clamp(floor(l * kEntrySteps), 0.0, kEntrySteps));
  uvec3 qh = uvec3(clamp(ceil(h * kEntrySteps), 0.0, kEntrySteps));
  return uvec4(key, segment, ql.x | (ql.y << 10u) | (ql.z << 20u),
               qh.x | (qh.y << 10u) | (qh.z << 20u));
}
uvec3 entryBoxLow(uvec4 e) { return (uvec3(e.z) >> uvec3(0u, 10u, 20u)) & 1023u; }
uvec3 entryBoxHigh(uvec4 e) { return (uvec3(e.w) >> uvec3(0u, 10u, 20u)) & 1023u; }

// The cells of a segment's padded box, [lo, hi] per axis. False when it has none: a position
// that is not finite (the comparison fails for NaN too), or a box over CSM_MAX_SEGMENT_CELLS cells (a
// segment stretched far beyond its rest length; see GpuSolver::gridStats). Such a segment
// is in no cell and looks for no contacts, so the pass stays symmetric and bounded.
bool segmentCells(vec3 p0, vec3 p1, out ivec3 lo, out ivec3 hi) {
  lo = ivec3(0);
  hi = ivec3(-1);
  // isnan as well as the bound: a compiler may assume that comparisons see no NaN (llvmpipe
  // drops them; tests/gpu/gpu_solver_test.cpp "a sample measures ..." caught it in measure.comp).
  if (any(isnan(p0)) || any(isnan(p1)) || !all(lessThan(abs(p0), vec3(1e30))) ||
      !all(lessThan(abs(p1), vec3(1e30))))
    return false;
  vec3 bl, bh;
  segmentBox(p0, p1, bl, bh);
  ivec3 l = cellOf(bl), h = cellOf(bh);
  ivec3 span = h - l + 1;
  const int most = CSM_MAX_SEGMENT_CELLS;
  if (any(greaterThan(span, ivec3(most))) || span.x * span.y * span.z > most) return false;
  lo = l;
  hi = h;
  return true;
}

// Bucket of a cell key (a 32-bit integer finalizer, so that the low bits, which the
// power-of-two mask keeps, mix all three coordinates). Several cells may share a bucket:
// entries carry their key.
uint bucketOf(uint key) {
  uint h = key * 0x9e3779b1u;
  h ^= h >> 16u;
  h *= 0x7feb352du;
  h ^= h >> 15u;
  return h & P.bucketMask;
}

// --- The volume grid (sim/solver/volume.h, csm::VolumeGrid). ---

const float kVolumeUnit = CSM_VOLUME_UNIT;

// The trilinear cell of head-frame position x: its lowest node and the fractions.
void volumeLocate(vec3 x, out ivec3 base, out vec3 f) {
  vec3 u = (x - P.volumeOrigin) / P.volumeCell;
  ivec3 top = ivec3(P.volumeDims) - 2;
  base = clamp(ivec3(floor(u)), ivec3(0), top);
  f = clamp(u - vec3(base), 0.0, 1.0);
}

uint volumeNode(ivec3 n) {
  return (uint(n.z) * P.volumeDims.y + uint(n.y)) * P.volumeDims.x + uint(n.x);
}

// Nodes of the volume grid.
int volumeNodes() { return int(P.volumeDims.x * P.volumeDims.y * P.volumeDims.z); }

// The nodes whose sums or gradient this frame's splat can have made non-zero: the box of the
// nodes it reached, one node more each way (the gradient's central differences), within the
// grid; returns its extent (0 where nothing was reached). The splat keeps the reached box in
// the two ivec4 after the nodes' sums (`sums`, a view of them), each axis as an atomicMax from
// a cleared 0: the second as the highest node + 1, the first as the dimension less the lowest
// node (so an untouched grid gives an empty box). Outside it every node's field is 0, as on
// the CPU, and is neither computed nor read.
ivec3 volumeBoxOf(ivec4 first, ivec4 second, out ivec3 low, out ivec3 high) {
  ivec3 dims = ivec3(P.volumeDims);
  low = max(dims - first.xyz - 1, ivec3(0));
  high = min(second.xyz, dims - 1);
  return max(high - low + 1, ivec3(0));
}
ivec3 volumeBox(isamplerBuffer sums, out ivec3 low, out ivec3 high) {
  return volumeBoxOf(texelFetch(sums, volumeNodes()), texelFetch(sums, volumeNodes() + 1), low,
                     high);
}
