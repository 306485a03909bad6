// The clamp as the beam's built-in end (ClampField in sim/solver/stiffness.h, METHOD.md section
// 4.3): behind the clamp the regions' members (the held particles and the ghosts) take the
// displacement u(tau) = a tau^2 from the head-carried rest shape, a fitted by least squares to
// the free particles' displacements over one window, reflected along the strand. The including pass defines how it reads a
// particle's x* (CSM_CLAMP_PREDICTED(base, j), j within the strand) and rest (readRest).
// Per strand (CSM_BIND_STRAND_STIFFNESS): stiffA.z pinned, stiffA.w the clamp's arc; stiffB.x
// the fit's reach (tau's unit, 0: no field), stiffB.y the end of the fit particles.

struct ClampField {
  vec3 a;         // m: the displacement at tau = 1
  float tau0;     // the root's tau
  float tauStep;  // a ghost's spacing in tau (the root segment's length)
};

// The field of the strand whose particles start at `first` (global index), x* at `base`.
ClampField clampFieldOf(uint first, uint base, int n, vec4 stiffA, vec4 stiffB, mat4 head) {
  ClampField f = ClampField(vec3(0.0), 0.0, 0.0);
  float reach = stiffB.x;
  if (!(reach > 0.0) || n < 2) return f;
  int pinned = int(stiffA.z), end = min(int(stiffB.y), n);
  vec3 previous = readRest(first).xyz;
  f.tau0 = -stiffA.w / reach;
  f.tauStep = length(readRest(first + 1u).xyz - previous) / reach;
  float arc = 0.0, sum4 = 0.0;
  vec3 sum2u = vec3(0.0);
  for (int j = 1; j < end; ++j) {
    vec3 r = readRest(first + uint(j)).xyz;
    arc += length(r - previous);
    previous = r;
    if (j < pinned) continue;
    float tau = (arc - stiffA.w) / reach, t2 = tau * tau;
    vec3 u = CSM_CLAMP_PREDICTED(base, j) - (head * vec4(r, 1.0)).xyz;
    sum4 += t2 * t2;
    sum2u += t2 * u;
  }
  f.a = sum4 > 0.0 ? sum2u / sum4 : vec3(0.0);
  // Reflected across the plane normal to the clamp's direction (the root segment carried by
  // the head): even across the strand, odd along it (ClampField::reflect).
  vec3 along = mat3(head) * (readRest(first + 1u).xyz - readRest(first).xyz);
  float l2 = dot(along, along);
  if (l2 > 0.0) f.a -= (2.0 * dot(f.a, along) / l2) * along;
  return f;
}

// The displacement behind the clamp at a given tau, held at its value 1.5 reaches deep
// (csm::kClampDepth).
vec3 clampShift(ClampField f, float tau) {
  tau = max(tau, -1.5);
  return (tau * tau) * f.a;
}

// The tau of particle j (< pinned: behind the clamp) of the strand starting at `first`.
float clampTauOf(uint first, int j, vec4 stiffA, vec4 stiffB) {
  if (!(stiffB.x > 0.0)) return 0.0;
  float arc = 0.0;
  for (int i = 1; i <= j; ++i)
    arc += length(readRest(first + uint(i)).xyz - readRest(first + uint(i - 1)).xyz);
  return (arc - stiffA.w) / stiffB.x;
}

// Adds the ghosts' shifts to a region's sums: ghost g at tau0 - g tauStep, rest -g d
// (root-relative), each of per-region mass mg.
void addGhostShifts(ClampField f, int ghosts, float mg, vec3 d, inout vec3 sumX,
                    inout mat3 sumA) {
  for (int g = 1; g <= ghosts; ++g) {
    vec3 shift = clampShift(f, f.tau0 - float(g) * f.tauStep);
    sumX += mg * shift;
    sumA -= outerProduct((mg * float(g)) * shift, d);
  }
}
