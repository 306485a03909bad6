// Shared by every pass of the GPU solver: binding points, the parameter block, indexing,
// quaternions, closest points of segments and the hash grid.
// The C++ side of SimParams and Substep is csm::gpu::SimParams / Substep in
// sim/gpu/gpu_params.h; a test compares the two layouts through GL's program introspection.
#include "sim/bindings.glsl"

struct SimParams {
  vec4 gravity;    // xyz, w unused
  vec4 windDir;    // xyz unit direction, w strength (m/s)
  vec4 windShape;  // x gusts, y gust frequency (Hz), z turbulence, w turbulence scale (m)
  vec4 stepping;   // x alpha, y strain limit epsilon, z hair radius r, w head friction
  vec4 contact;    // x penalty stiffness (1/s^2), y normal damping (1/s), z friction, w frame dt
  vec4 misc;       // x DFTL, y wind drag (1/s), z cell slack, w prefilter slack
  ivec4 ints;      // x pinned, y stiffness window w, z rotation iterations, w head spheres
  uvec4 flags;     // x strain limiting, y head collision, z wind, w contact forces valid
  uvec4 counts;    // x particles, y strands, z segments, w pair capacity (0 = do not record)
  uvec4 grid;      // x bucket mask (buckets - 1), y P1, z P2, w unused
  uvec4 runs[3];   // bucket offsets of the 9 (dy, dz) runs of three x-neighbouring cells
};

struct Substep {
  mat4 head;       // head pose at the end of the step: pinned roots follow it
  mat4 headDelta;  // start-of-step pose after the inverse of the end pose (head friction)
  vec4 time;       // x time at the start of the step, y h, z unused, w velocity kept by damping
};

layout(std430, binding = CSM_BIND_PARAMS) readonly buffer Params {
  SimParams P;
  Substep S[];
};

// Items beyond 65535 work groups are dispatched as a 2D grid of groups (the GL 4.3 minimum
// for gl_NumWorkGroups.x); this flattens it back. A macro: gl_WorkGroupSize exists only
// after the pass declares its local size, below this include.
#define globalIndex()                                                                     \
  ((gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + \
   gl_LocalInvocationID.x)

// --- Quaternions as vec4(x, y, z, w), Hamilton products, like Eigen::Quaternion. ---

vec4 quatMul(vec4 a, vec4 b) {
  return vec4(a.w * b.xyz + b.w * a.xyz + cross(a.xyz, b.xyz), a.w * b.w - dot(a.xyz, b.xyz));
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
// R's columns toward A's by the torque they make, scaled like a Newton step. Robust when A is
// rank-deficient (straight strands). Same arithmetic as csm::extractRotation, in float.
vec4 extractRotation(mat3 A, vec4 q, int iterations) {
  for (int it = 0; it < iterations; ++it) {
    mat3 R = quatToMat(q);
    vec3 torque = cross(R[0], A[0]) + cross(R[1], A[1]) + cross(R[2], A[2]);
    float scale = abs(dot(R[0], A[0]) + dot(R[1], A[1]) + dot(R[2], A[2])) + 1e-9;
    vec3 omega = torque / scale;
    float angle = length(omega);
    if (angle < 1e-9) break;
    float half_ = 0.5 * angle;
    q = quatMul(vec4(sin(half_) * (omega / angle), cos(half_)), q);
    q = q / length(q);
  }
  return q;
}

// --- Hair-hair collision. ---

// Closest points of segments p0-p1 and q0-q1 (Ericson, Real-Time Collision Detection,
// section 5.1.9), as csm::closestSegmentPoints. Returns the squared distance.
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

// A segment index carried in a float's bits. Offset so that the pattern is a normal float
// (indices < 2^27, the particle limit, give 2.0 .. 2^17): a GPU may flush denormals even
// when it only moves them.
float encodeIndex(uint i) { return uintBitsToFloat(i + 0x40000000u); }
uint decodeIndex(float f) { return floatBitsToUint(f) - 0x40000000u; }

// The grid's cell edge: the longest segment plus 2r, so two segments closer than 2r have
// midpoints in the same or neighbouring cells. The slack (a few float ulps) keeps that true
// when the midpoints are rounded.
float cellSize(uint longestBits) {
  return (uintBitsToFloat(longestBits) + 2.0 * P.stepping.z) * P.misc.z;
}

ivec3 cellOf(vec3 midpoint, float cell) { return ivec3(floor(midpoint / cell)); }

// A linear hash: x-neighbouring cells fall into consecutive buckets, so the 27 neighbours are
// 9 runs of 3 buckets, at offsets independent of the cell (chosen on the CPU so that the 27
// buckets are distinct). Arithmetic wraps mod 2^32, and the bucket count is a power of two.
uint bucketOf(ivec3 c) {
  return (uint(c.x) + uint(c.y) * P.grid.y + uint(c.z) * P.grid.z) & P.grid.x;
}
