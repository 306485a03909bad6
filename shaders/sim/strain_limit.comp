// Step 6 of DESIGN.md section 1, one invocation per strand: the strand contacts' corrections
// (contact_solve.comp: each particle moves by the mean of what its segments sent), strain
// limiting in one sweep from root to tip (paper section 3.2: each segment is fixed against an already final parent, so
// no iteration), pushing out of the head (its distance field, or its spheres), Coulomb friction against the head and DFTL
// (Mueller et al. 2012) on the strain-limit correction, as CpuSolver::limitStrain. The sweep
// is sequential by nature; a strand is one invocation and the particle's parent stays in
// registers.
#include "sim/common.glsl"
#include "sim/head_field.glsl"

layout(local_size_x = CSM_STRAND_GROUP) in;

layout(binding = CSM_TEX_REST) uniform samplerBuffer restTex;
layout(std430, binding = CSM_BIND_POSITION) buffer Position { vec4 pos[]; };
layout(std430, binding = CSM_BIND_VELOCITY) buffer Velocity { vec4 vel[]; };
layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_STRAND_ORDER) readonly buffer StrandOrder { uint strandOrder[]; };
layout(std430, binding = CSM_BIND_SPHERES) readonly buffer Spheres { vec4 spheres[]; };
layout(std430, binding = CSM_BIND_STRAND_STIFFNESS) readonly buffer StrandStiffness {
  vec4 strandStiffness[];
};
layout(std430, binding = CSM_BIND_CORRECTION) readonly buffer Correction { vec4 correction[]; };

uniform uint substep;

// Pushes p out of one sphere onto its surface. With a strain limit, the push keeps the segment
// from `prev` no longer than maxLength: when the radial projection is out of reach, take the
// nearest point of the circle where the sphere meets the ball of reach around prev. (Moving
// along the chord toward prev instead would jump: a chord between two points on the sphere
// always cuts through it.) The float twin of pushOutOfSphere in sim/cpu/cpu_solver.cpp.
bool pushOutOfSphere(inout vec3 p, vec3 prev, vec3 c, float radius, float maxLength) {
  vec3 d = p - c;
  float len2 = dot(d, d);
  if (len2 >= radius * radius) return false;
  float len = sqrt(len2);
  vec3 target = c + (len > 1e-15 ? d / len : vec3(0.0, 1.0, 0.0)) * radius;
  p = target;
  if (maxLength <= 0.0 || length(target - prev) <= maxLength) return true;
  vec3 toPrev = prev - c;
  float dist = length(toPrev);
  // No circle when prev is inside the sphere, or out of reach of it; keep the projection.
  if (dist < 1e-15 || dist + maxLength < radius || dist - radius > maxLength) return true;
  vec3 u = toPrev / dist;
  float a = (radius * radius - maxLength * maxLength + dist * dist) / (2.0 * dist);
  float rho = sqrt(max(0.0, radius * radius - a * a));
  vec3 centre = c + a * u;
  vec3 side = target - centre;
  side -= dot(side, u) * u;
  float sideLen = length(side);
  if (sideLen < 1e-15) return true;
  p = centre + side * (rho / sideLen);
  return true;
}

// How far p (world) lies outside the head's surface (not inflated): its field, or the nearest
// of its spheres.
float outsideHead(vec3 p, mat4 head, uint sphereBase) {
  if (headIsField()) return headFieldSample(toHeadFrame(head, p)).w;
  float d = 1e30;
  for (int k = 0; k < P.ints.w; ++k) {
    vec4 sp = spheres[sphereBase + uint(k)];
    d = min(d, length(p - sp.xyz) - sp.w);
  }
  return d;
}

// One push of p out of the head inflated by r, within reach of prev where it can. `normal`
// gets the field's outward normal (spheres: left as it is); `clearance` how far the point it
// returns lies outside the head, where the push read it (else kUnknownClearance).
bool pushHead(inout vec3 p, vec3 prev, mat4 head, uint sphereBase, float r, float maxLength,
              inout vec3 normal, out float clearance) {
  clearance = kUnknownClearance;
  if (headIsField()) {
    vec3 n;
    bool touching = pushOutOfHeadField(p, prev, head, r, maxLength, n, clearance);
    if (touching) normal = n;
    return touching;
  }
  // Overlapping spheres can push a particle into each other: repeat until it is clear.
  bool touching = false;
  for (int pass = 0; pass < 4; ++pass) {
    bool moved = false;
    for (int k = 0; k < P.ints.w; ++k) {
      vec4 sp = spheres[sphereBase + uint(k)];
      moved = pushOutOfSphere(p, prev, sp.xyz, sp.w + r, maxLength) || moved;
    }
    touching = touching || moved;
    if (!moved) break;
  }
  return touching;
}

// Pushes p (where the strain limit put it, within maxLength of prev) out of the head and keeps
// it within reach of prev: the push, and where that is out of reach or still in the head (p went
// deep, where the surface nearest is another part of the head than the one prev lies over; a
// concave part, where the tangent plane cuts into the head) the push again from the nearest
// point of reach, twice; the last resort, the point where the segment from prev enters the
// head, by bisection. "In the head": deeper than the surface and than prev. The float twin of
// HeadCollider::pushOut in sim/cpu/cpu_solver.cpp.
bool pushOutOfHead(inout vec3 p, vec3 prev, mat4 head, uint sphereBase, float r, float maxLength,
                   inout vec3 normal) {
  float clearance;
  if (!pushHead(p, prev, head, sphereBase, r, maxLength, normal, clearance)) return false;
  if (maxLength <= 0.0) return true;
  float level = 1e30;  // min(0, how far prev lies outside), read once when needed
  for (int pass = 0;; ++pass) {
    float len = length(p - prev);
    bool reach = len <= maxLength * (1.0 + 1e-5);
    // The push's own last read where it has one (the field's projection): no second read.
    float depth =
        clearance != kUnknownClearance ? clearance : outsideHead(p, head, sphereBase);
    if (reach && depth >= 0.0) return true;
    if (level == 1e30) level = min(0.0, outsideHead(prev, head, sphereBase));
    if (reach && depth >= level) return true;
    if (!reach) p = prev + (p - prev) * (maxLength / len);
    if (pass == 2) break;
    pushHead(p, prev, head, sphereBase, r, maxLength, normal, clearance);
  }
  float lo = 0.0, hi = 1.0;
  for (int k = 0; k < 20; ++k) {
    float mid = 0.5 * (lo + hi);
    if (outsideHead(prev + mid * (p - prev), head, sphereBase) >= level) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  p = prev + lo * (p - prev);
  if (headIsField()) {
    vec3 grad = headFieldSample(toHeadFrame(head, p)).xyz;
    if (length(grad) > 1e-12) normal = mat3(head) * normalize(grad);
  }
  return true;
}

void main() {
  uint id = globalIndex();
  if (id >= P.counts.y) return;
  uint s = strandOrder[id];
  uint a = strandFirst[s];
  int n = int(strandFirst[s + 1u] - a);
  int pinned = int(strandStiffness[s].z);
  int first = max(1, pinned);
  if (n <= first) return;

  Substep st = S[substep];
  float h = st.time.y;
  bool limit = P.flags.x != 0u;
  bool headCollide = P.flags.y != 0u;
  bool contacts = P.flags.w != 0u;
  float epsilon = P.stepping.y;
  float r = P.stepping.z;
  float friction = P.stepping.w;
  float dftl = P.misc.x;
  int sphereCount = P.ints.w;
  uint sphereBase = substep * uint(sphereCount);

  vec3 restPrev = texelFetch(restTex, int(a) + first - 1).xyz;
  vec3 xPrev = pos[a + uint(first - 1)].xyz;
  vec3 vPrev = vel[a + uint(first - 1)].xyz;
  bool prevFree = first - 1 >= pinned;  // DFTL only corrects free particles
  for (int i = first; i < n; ++i) {
    uint p = a + uint(i);
    vec3 restHere = texelFetch(restTex, int(p)).xyz;
    vec3 x = pos[p].xyz;
    vec3 v = vel[p].xyz;
    if (contacts) {
      // A change of velocity too, as CpuSolver::limitStrain.
      vec4 c = correction[2u * (p - 1u) + 1u];
      if (i + 1 < n) c += correction[2u * p];
      if (c.w > 0.0) {
        vec3 moved = c.xyz / c.w;
        x += moved;
        v += moved / h;
      }
    }
    vec3 start = x;
    float maxLength = limit ? (1.0 + epsilon) * length(restHere - restPrev) : 0.0;
    if (limit) {
      vec3 d = x - xPrev;
      float len = length(d);
      if (len > maxLength) x = xPrev + d * (maxLength / len);
    }
    vec3 strained = x;
    vec3 fieldNormal = vec3(0.0);
    // A non-finite particle stays so, for the NaN check to see: the pushes below would put it
    // on the head (their fallback normal) as if nothing had happened.
    bool collide = headCollide && !any(isnan(x)) && !any(isinf(x));
    bool touching = collide && pushOutOfHead(x, xPrev, st.head, sphereBase, r, maxLength,
                                             fieldNormal);
    vec3 vBeforeHead = v + (strained - start) / h;
    v = vBeforeHead + (x - strained) / h;
    if (touching) {
      // Coulomb friction against the moving head: the tangential speed relative to the surface
      // loses at most mu times the normal speed the contact took away this step.
      vec3 surfaceVel = (x - (st.headDelta * vec4(x, 1.0)).xyz) / h;
      vec3 nrm = fieldNormal;
      if (!headIsField()) {
        vec4 nearest = spheres[sphereBase];
        float best = length(x - nearest.xyz) - nearest.w;
        for (int k = 1; k < sphereCount; ++k) {
          vec4 sp = spheres[sphereBase + uint(k)];
          float dist = length(x - sp.xyz) - sp.w;
          if (dist < best) {
            best = dist;
            nearest = sp;
          }
        }
        nrm = normalize(x - nearest.xyz);
      }
      float vnBefore = dot(vBeforeHead - surfaceVel, nrm);
      vec3 rel = v - surfaceVel;
      float vn = max(0.0, dot(rel, nrm));
      vec3 vt = rel - dot(rel, nrm) * nrm;
      float vtLen = length(vt);
      float taken = friction * max(0.0, vn - vnBefore);
      float keepT = vtLen > taken ? 1.0 - taken / vtLen : 0.0;
      v = surfaceVel + vn * nrm + keepT * vt;
    }
    // Dynamic follow-the-leader: the parent takes back part of the velocity its child got
    // from the strain-limit correction, against the heavy-tip look.
    if (dftl > 0.0 && prevFree) vPrev -= dftl * (strained - start) / h;
    vel[p - 1u] = vec4(vPrev, 0.0);
    pos[p] = vec4(x, 1.0);
    restPrev = restHere;
    xPrev = x;
    vPrev = v;
    prevFree = i >= pinned;
  }
  vel[a + uint(n - 1)] = vec4(vPrev, 0.0);
}
