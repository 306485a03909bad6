// The clamp as the beam's built-in end (ClampField in sim/solver/stiffness.h, METHOD.md section
// 4.3): behind the clamp the regions' members (the held particles and the ghosts) take the
// displacement u(tau) = a tau^2 from the head-carried rest shape, a fitted by least squares to
// the free particles' displacements over one window, reflected along the strand. The including
// pass defines how it reads a particle's x* (CSM_CLAMP_PREDICTED(base, j), j within the strand)
// and rest (readRest). Static data, built on the CPU (csm::Regions): each particle's tau in its
// rest's w (CSM_BIND_REST), the end of the strand's fit particles in its stiffness's w.

struct ClampField {
  vec3 a;         // m: the displacement at tau = 1
  float tau0;     // the root's tau
  float tauStep;  // a ghost's spacing in tau (the root segment's length)
};

// The field of the strand whose particles start at `first` (global index), x* at `base`;
// stiff = its CSM_BIND_STRAND_STIFFNESS entry (z pinned (pinnedOf), w the fit's end: none when
// <= the pinned).
ClampField clampFieldOf(uint first, uint base, int n, vec4 stiff, mat4 head) {
  ClampField f = ClampField(vec3(0.0), 0.0, 0.0);
  int pinned = pinnedOf(stiff), end = min(int(stiff.w), n);
  if (end <= pinned || n < 2) return f;
  vec4 root = readRest(first), next = readRest(first + 1u);
  f.tau0 = root.w;
  f.tauStep = next.w - root.w;
  // Least squares of u_j = a tau_j^2 over the fit particles.
  float sum4 = 0.0;
  vec3 sum2u = vec3(0.0);
  for (int j = pinned; j < end; ++j) {
    vec4 r = readRest(first + uint(j));
    float t2 = r.w * r.w;
    sum4 += t2 * t2;
    sum2u += t2 * (CSM_CLAMP_PREDICTED(base, j) - (head * vec4(r.xyz, 1.0)).xyz);
  }
  f.a = sum4 > 0.0 ? sum2u / sum4 : vec3(0.0);
  // Reflected across the plane normal to the clamp's direction (the root segment carried by
  // the head): even across the strand, odd along it (ClampField::reflect).
  vec3 along = mat3(head) * (next.xyz - root.xyz);
  float l2 = dot(along, along);
  if (l2 > 0.0) f.a -= (2.0 * dot(f.a, along) / l2) * along;
  return f;
}

// The displacement behind the clamp at a given tau, held at its value CSM_CLAMP_DEPTH reaches
// deep (csm::kClampDepth).
vec3 clampShift(ClampField f, float tau) {
  tau = max(tau, -float(CSM_CLAMP_DEPTH));
  return (tau * tau) * f.a;
}

// a across the clamp's direction `along` (any length): what the clamp's pull scales
// (ClampField::across).
vec3 clampAcross(ClampField f, vec3 along) {
  float l2 = dot(along, along);
  return l2 > 0.0 ? f.a - (dot(f.a, along) / l2) * along : f.a;
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
