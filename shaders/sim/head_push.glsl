// The strain limit's sweep, one particle at a time (METHOD.md section 2.7), shared by
// strain_limit.comp (one invocation per strand) and strand_step.comp / strand_strain.comp (a
// strand's particles in one work group, the sweep over them in shared memory): the strand
// contacts' correction, the strain limit against the already final parent (paper section 3.2),
// the push out of the head (its distance field with CSM_HEAD_FIELD, else its spheres), Coulomb
// friction against the head, and DFTL (Mueller et al. 2012) on the parent's velocity, as
// sweepParticle in sim/solver/cpu_steps.cpp. The including pass declares spheres[].
#ifdef CSM_HEAD_FIELD
#include "sim/head_field.glsl"
#endif

// Whether p lies within reach of prev, len = |p - prev| against the segment's limit maxLength,
// give or take the rounding of a length (CSM_REACH_SLACK_FLOAT) and of the positions themselves
// (CSM_REACH_ROUNDING_FLOAT: metres from the origin a float position rounds by more than 1e-5
// of a segment).
bool withinReach(float len, float maxLength, vec3 p, vec3 prev) {
  vec3 size = max(abs(p), abs(prev));
  float largest = max(size.x, max(size.y, size.z));
  return len <= maxLength * (1.0 + CSM_REACH_SLACK_FLOAT) + CSM_REACH_ROUNDING_FLOAT * largest;
}

#ifdef CSM_HEAD_FIELD
// A push's point whose depth it did not read (the circle's).
const float kUnknownClearance = -1e30;

// Pushes p (where the strain limit put it, within maxLength of prev) out of the body's distance
// field (the union of its parts at the step's poses, bodySample, read in world space) inflated
// by r and keeps it within reach of prev; `normal` gets the field's outward normal where it
// touched. The float twin of pushOutOfHead in sim/solver/cpu_steps.cpp on a field head
// (pushOutOfHead below: the same for the spheres).
// - The push: along the field's normal by what is left, twice at most (the field is close to a
//   distance, not exactly one); out of reach, the nearest point of the circle where the
//   tangent plane there meets the ball of reach around prev.
// - Where that is out of reach or still in the head (p went deep, nearer another part of the
//   head than the one prev lies over; a concave part, where the tangent plane cuts into it),
//   the push again from the nearest point of reach, twice. "In the head": deeper than the
//   surface and than prev.
// - The last resort: the point where the segment from prev enters the head, by bisection, and
//   the field's normal there.
// One loop that reads the field once an iteration, the state saying which read comes next:
// llvmpipe runs both sides of every branch, and every loop body at least once, but a loop only
// while one of its lanes still needs it. Written straight, the eight places that read the field
// cost eight reads a particle however few it needed; here a particle clear of the head costs
// one, a plain push two or three, and the bisection's 20 come only where a lane needs them
// (Fig. 1, head only, llvmpipe: strain limiting 49.6 -> 25.5 ms a frame, the same positions to
// the bit).
bool pushOutOfFieldHead(inout vec3 p, vec3 prev, Substep st, float r, float maxLength,
                        inout vec3 normal) {
  // What the next read is of: a push's first read at p, a step of the push, how far p lies
  // outside (after a push that left it on the circle), how far prev lies outside, the
  // bisection, the gradient where it ended; done.
  const int kPush = 0, kStep = 1, kDepth = 2, kLevel = 3, kBisect = 4, kGradient = 5, kDone = 6;
  const vec3 up = mat3(st.head) * vec3(0.0, 1.0, 0.0);
  int state = kPush;
  bool touching = false;  // the first push found p closer than r to the surface
  vec3 local = vec3(0.0), n = up;
  int steps = 0, pass = 0, bisections = 0;
  // With a torso, up to eight steps: one out of a part may end in the other, in the crease where
  // they meet (pushOutOfBodyField in sim/solver/cpu_steps.cpp).
  int maxSteps = P.torsoIsField != 0u ? 8 : 2;
  float clearance = kUnknownClearance, level = 1e30, depth = 0.0, len = 0.0;
  bool reach = false;
  float lo = 0.0, hi = 1.0, mid = 0.0;
  // At most 3 reads for the first push (9 with a torso), 5 + 4 + 1 for the passes (17 + 16 + 1),
  // 20 + 1 at the end.
  for (int guard = 0; state != kDone && guard < 80; ++guard) {
    vec3 q = state == kStep     ? local
             : state == kLevel  ? prev
             : state == kBisect ? prev + mid * (p - prev)
                                : p;
    vec4 s = bodySample(st, q);
    bool pushed = false, checkReach = false, checkDepth = false, checkLevel = false;
    if (state == kPush) {
      // A push's first read, at p.
      local = q;
      clearance = s.w;
      if (s.w >= r) {
        if (!touching) state = kDone;  // not touching: p as it was
        checkReach = touching;         // a pass's push that found p clear
      } else {
        n = up;
        steps = 0;
        state = kStep;
        pushed = !(steps < maxSteps && s.w < r);  // a NaN distance takes no step, as the loop's test
      }
    } else if (state == kStep) {
      pushed = !(steps < maxSteps && s.w < r);  // else one more step (below)
    } else if (state == kDepth) {
      depth = s.w;
      checkDepth = true;
    } else if (state == kLevel) {
      level = min(0.0, s.w);
      checkLevel = true;
    } else if (state == kBisect) {
      if (s.w >= level) {
        lo = mid;
      } else {
        hi = mid;
      }
      if (++bisections < 20) {
        mid = 0.5 * (lo + hi);
      } else {
        p = prev + lo * (p - prev);
        state = kGradient;
      }
    } else if (state == kGradient) {
      if (length(s.xyz) > 1e-12) normal = normalize(s.xyz);
      state = kDone;
    }
    // A step of the push: along the field's normal by what is left.
    if (state == kStep && !pushed) {
      float g = length(s.xyz);
      n = g > 1e-12 ? s.xyz / g : up;
      local += (r - s.w) * n;
      ++steps;
    }
    if (pushed) {
      // The push's end: onto the surface, or the circle within reach of prev.
      vec3 target = local;
      vec3 nw = n;
      p = target;
      clearance = s.w;
      normal = nw;
      if (!(maxLength <= 0.0 || length(target - prev) <= maxLength)) {
        float above = dot(prev - target, nw);
        if (!(abs(above) >= maxLength)) {  // else no circle: the projection
          vec3 centre = prev - above * nw;
          vec3 side = target - centre;
          float sideLen = length(side);
          if (!(sideLen < 1e-15)) {
            p = centre + side * (sqrt(maxLength * maxLength - above * above) / sideLen);
            clearance = kUnknownClearance;
          }
        }
      }
      touching = true;
      if (maxLength <= 0.0) {
        state = kDone;
      } else {
        checkReach = true;
      }
    }
    // A pass, as in pushOutOfHead below: within reach and outside, done; else toward prev.
    if (checkReach) {
      len = length(p - prev);
      reach = withinReach(len, maxLength, p, prev);
      if (clearance != kUnknownClearance) {
        depth = clearance;
        checkDepth = true;
      } else {
        state = kDepth;
      }
    }
    if (checkDepth) {
      if (reach && depth >= 0.0) {
        state = kDone;
      } else if (level == 1e30) {
        state = kLevel;
      } else {
        checkLevel = true;
      }
    }
    if (checkLevel) {
      if (reach && depth >= level) {
        state = kDone;
      } else {
        if (!reach) p = prev + (p - prev) * (maxLength / len);
        if (pass == 2) {
          mid = 0.5 * (lo + hi);
          state = kBisect;
        } else {
          ++pass;
          state = kPush;
        }
      }
    }
  }
  return touching;
}

#else  // the head's spheres

// Pushes p out of one sphere onto its surface. With a strain limit, the push keeps the segment
// from `prev` no longer than maxLength: when the radial projection is out of reach, take the
// nearest point of the circle where the sphere meets the ball of reach around prev. (Moving
// along the chord toward prev instead would jump: a chord between two points on the sphere
// always cuts through it.) The float twin of pushOutOfSphere in sim/solver/cpu_steps.cpp.
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

// How far p (world) lies outside the nearest of the head's spheres.
float outsideHead(vec3 p, uint sphereBase) {
  float d = 1e30;
  for (int k = 0; k < P.headSpheres; ++k) {
    vec4 sp = spheres[sphereBase + uint(k)];
    d = min(d, length(p - sp.xyz) - sp.w);
  }
  return d;
}

// One push of p out of the spheres inflated by r, within reach of prev where it can.
// Overlapping spheres can push a particle into each other: repeated until it is clear.
bool pushHead(inout vec3 p, vec3 prev, uint sphereBase, float r, float maxLength) {
  bool touching = false;
  for (int pass = 0; pass < 4; ++pass) {
    bool moved = false;
    for (int k = 0; k < P.headSpheres; ++k) {
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
// deep, where the nearest surface is another sphere than the one prev lies over) the push again
// from the nearest point of reach, twice; the last resort, the point where the segment from prev
// enters the head, by bisection. "In the head": deeper than the surface and than prev. The float
// twin of pushOutOfHead in sim/solver/cpu_steps.cpp (pushOutOfFieldHead: the same for the
// distance field).
bool pushOutOfHead(inout vec3 p, vec3 prev, uint sphereBase, float r, float maxLength) {
  if (!pushHead(p, prev, sphereBase, r, maxLength)) return false;
  if (maxLength <= 0.0) return true;
  float level = 1e30;  // min(0, how far prev lies outside), read once when needed
  for (int pass = 0;; ++pass) {
    float len = length(p - prev);
    bool reach = withinReach(len, maxLength, p, prev);
    float depth = outsideHead(p, sphereBase);
    if (reach && depth >= 0.0) return true;
    if (level == 1e30) level = min(0.0, outsideHead(prev, sphereBase));
    if (reach && depth >= level) return true;
    if (!reach) p = prev + (p - prev) * (maxLength / len);
    if (pass == 2) break;
    pushHead(p, prev, sphereBase, r, maxLength);
  }
  float lo = 0.0, hi = 1.0;
  for (int k = 0; k < 20; ++k) {
    float mid = 0.5 * (lo + hi);
    if (outsideHead(prev + mid * (p - prev), sphereBase) >= level) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  p = prev + lo * (p - prev);
  return true;
}

#endif

// One particle after the first free one: x, v where shape matching left it, in and out; `c` the
// strand contacts' correction sent to it (w: how many sent; applied when `contacts`); xPrev, the
// parent's final position; vPrev, the parent's velocity, which DFTL corrects (when prevFree).
// One segment of a strand held at both ends limited against its neighbour `anchor`, already
// final (limitToward in sim/solver/cpu_steps.cpp): x moves toward it, v with it. Whether x moved.
bool limitToward(inout vec3 x, inout vec3 v, vec3 anchor, float restLength, float h) {
  vec3 d = x - anchor;
  float len = length(d), most = (1.0 + P.strainLimit) * restLength;
  if (!(len > most)) return false;
  vec3 to = anchor + d * (most / len);
  v += (to - x) / h;
  x = to;
  return true;
}

// The point nearest x in both balls (a, ra) and (b, rb) (intoBothBalls in
// sim/solver/cpu_steps.cpp).
vec3 intoBothBalls(vec3 x, vec3 a, float ra, vec3 b, float rb) {
  vec3 pa = length(x - a) > ra ? a + (x - a) * (ra / length(x - a)) : x;
  if (length(pa - b) <= rb * (1.0 + 1e-6)) return pa;
  vec3 pb = length(x - b) > rb ? b + (x - b) * (rb / length(x - b)) : x;
  if (length(pb - a) <= ra * (1.0 + 1e-6)) return pb;
  vec3 ab = b - a;
  float d = length(ab);
  if (!(d > 0.0) || d >= ra + rb) return a + ab * (ra / max(ra + rb, 1e-30));
  vec3 u = ab / d;
  float along = (d * d + ra * ra - rb * rb) / (2.0 * d);
  float ring = sqrt(max(0.0, ra * ra - along * along));
  vec3 w = (x - a) - dot(x - a, u) * u;
  if (length(w) < 1e-30) w = abs(u.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  w -= dot(w, u) * u;
  return a + along * u + ring * normalize(w);
}

void sweepParticle(vec3 restHere, vec3 restPrev, bool contacts, vec4 c, vec3 xPrev, bool prevFree,
                   Substep st, uint sphereBase, inout vec3 x, inout vec3 v, inout vec3 vPrev) {
  float h = st.h;
  bool limit = P.strainLimiting != 0u;
  bool headCollide = P.headCollision != 0u;
  float epsilon = P.strainLimit;
  float r = P.radius;
  float friction = P.headFriction;
  float dftl = P.dftl;
  int sphereCount = P.headSpheres;
      if (contacts) {
        // A change of velocity too, as sweepParticle in sim/solver/cpu_steps.cpp.
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
  #ifdef CSM_HEAD_FIELD
      bool touching = collide && pushOutOfFieldHead(x, xPrev, st, r, maxLength, fieldNormal);
  #else
      bool touching = collide && pushOutOfHead(x, xPrev, sphereBase, r, maxLength);
  #endif
      vec3 vBeforeHead = v + (strained - start) / h;
      v = vBeforeHead + (x - strained) / h;
      if (touching) {
        // Coulomb friction against the moving head: the tangential speed relative to the surface
        // loses at most mu times the normal speed the contact took away this step.
        // The part it touches (the head, or the torso), and where its surface point there was
        // at the step's start.
        vec3 nrm = fieldNormal;
        bool torso = false;
  #ifdef CSM_HEAD_FIELD
        if (P.torsoIsField != 0u) {
          int part;
          bodySample(st, x, part);
          torso = part == 1;
        }
  #else
        {
          vec4 nearest = spheres[sphereBase];
          float best = length(x - nearest.xyz) - nearest.w;
          int nearestIndex = 0;
          for (int k = 1; k < sphereCount; ++k) {
            vec4 sp = spheres[sphereBase + uint(k)];
            float dist = length(x - sp.xyz) - sp.w;
            if (dist < best) {
              best = dist;
              nearest = sp;
              nearestIndex = k;
            }
          }
          nrm = normalize(x - nearest.xyz);
          torso = nearestIndex >= P.torsoSphereFirst;
        }
  #endif
        vec3 was = torso ? quatTurn(st.torsoDeltaRotation, x) + st.torsoDeltaTranslation.xyz
                         : (st.headDelta * vec4(x, 1.0)).xyz;
        vec3 surfaceVel = (x - was) / h;
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
}
