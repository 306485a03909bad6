// Steps 1-5 of METHOD.md section 2 on the per-particle path, one invocation per particle, whole
// strands to a work group (strand_group.glsl): prediction (predict.glsl), shape matching of every
// region, goals and integration, the arithmetic of shape_match.comp with its prefix sums as
// segmented scans in shared memory. With CSM_SWEEP (modes without strand contacts, whose
// corrections would come between) the strain limit's sweep too (head_push.glsl), over the strand
// in shared memory: one pass a substep, where the per-strand path runs three.
//
// Per particle: x* (predict), then the sums m, m y, m ȳ, m y ȳᵀ of the particles up to it
// (y = x* - x*_root, ȳ = x̄ - x̄_root, per-region mass m) as a scan; each particle's region
// [lo, hi] (regionTex) takes its sums as differences of two scanned slots and extracts R; a
// second scan of R_k and c_k - R_k c̄_k gives each particle the sums over the regions that hold
// it, hence its goal; then x = x* + alpha (g - x*), v = (x - x_old) / h.
#include "sim/common.glsl"

#include "sim/particle_reads.glsl"
layout(std430, binding = CSM_BIND_POSITION) writeonly buffer Position { vec4 pos[]; };
layout(std430, binding = CSM_BIND_VELOCITY) writeonly buffer Velocity { vec4 vel[]; };
layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_ROTATION) buffer Rotation { vec4 rotation[]; };
layout(std430, binding = CSM_BIND_STRAND_STIFFNESS) readonly buffer StrandStiffness {
  vec4 strandStiffness[];
};
layout(std430, binding = CSM_BIND_SPHERES) readonly buffer Spheres { vec4 spheres[]; };

uniform uint substep;

#include "sim/predict.glsl"
#ifdef CSM_SWEEP
#include "sim/head_push.glsl"
#endif
#include "sim/strand_group.glsl"
// The clamp's field reads x* from the strand's slots in shared memory (base: the root's slot).
#define CSM_CLAMP_PREDICTED(base, j) shA[(base) + uint(j)].xyz
#include "sim/clamp_field.glsl"

void main() {
  Slot o = groupSlot();
  uint lid = gl_LocalInvocationID.x;
  Substep st = S[substep];
  vec4 stiff = strandStiffness[o.s];
  int pinned = pinnedOf(stiff);
  bool held = heldAt(stiff, o.j, o.n);
  vec3 vPred = vec3(0.0);
  vec3 xp = o.live ? predictParticle(o.p, o.a, o.a + uint(o.n), held, st, vPred) : vec3(0.0);
  vec4 region = o.live ? readRegion(o.p) : vec4(0.0);
  // A slot past the group's end reads nothing (a fetch out of range is undefined).
  vec4 restTau = o.live ? readRest(o.p) : vec4(0.0);  // w: its tau (clamp_field.glsl)
  vec3 rest = restTau.xyz;
  vec3 rest0 = o.live ? readRest(o.a).xyz : vec3(0.0);
  vec3 restNext = o.live ? readRest(int(o.a) + min(1, o.n - 1)).xyz : vec3(0.0);

  // The root's x*, to every slot of its strand.
  shA[lid] = vec4(xp, 0.0);
  barrier();
  vec3 origin = shA[o.root].xyz;
  // The built-in end (clamp_field.glsl): the held particles and the ghosts of this slot's
  // region take the free strand's curvature at the clamp, continued. The field is the strand's:
  // its root's slot fits it once and leaves it in shB and shC, free until the first scan, with
  // its a across the clamp's direction D (what the clamp's pull scales).
  vec3 d = o.n > 1 ? restNext - rest0 : vec3(0.0);
  vec3 D = mat3(st.head) * d;
  if (o.live && o.j == 0) {
    ClampField f = clampFieldOf(o.a, o.root, o.n, stiff, st.head);
    shB[lid] = vec4(f.a, f.tau0);
    shC[lid] = vec4(f.tauStep, clampAcross(f, D));
  }
  barrier();
  int ghosts = max(0, -int(region.z));
  bool behind = o.live && o.j < pinned;
  // This slot's region reaches behind the clamp: it reads the field, and a free particle here
  // has the clamp's pull (csm::Regions::clampPull, zero elsewhere).
  bool nearClamp = o.live && int(region.z) < pinned;
  ClampField field = ClampField(vec3(0.0), 0.0, 0.0);
  vec3 across = vec3(0.0);
  if (nearClamp) {
    field = ClampField(shB[o.root].xyz, shB[o.root].w, shC[o.root].x);
    across = shC[o.root].yzw;
  }
  vec3 shift = behind ? clampShift(field, restTau.w) : vec3(0.0);
  barrier();

  // Scan 1: m, m y (shA), m ȳ and A's first entry (shB), the rest of A = m y ȳᵀ (shC, shD).
  float m = region.x;
  vec3 y = xp + shift - origin, yr = rest - rest0;
  mat3 A1 = outerProduct(m * y, yr);
  vec4 v0 = vec4(m, m * y), v1 = vec4(m * yr, A1[0][0]);
  vec4 v2 = vec4(A1[0][1], A1[0][2], A1[1][0], A1[1][1]);
  vec4 v3 = vec4(A1[1][2], A1[2][0], A1[2][1], A1[2][2]);
  strandScan(o, v0, v1, v2, v3);

  // This slot's region [lo, hi]: its centroids, A and R (as shape_match.comp's second loop).
  int n = o.n;
  int lo = clamp(int(region.z), 0, n - 1), hi = clamp(int(region.w), lo, n - 1);
  vec4 s0 = rangeSumA(o, lo, hi), s1 = rangeSumB(o, lo, hi);
  vec4 s2 = rangeSumC(o, lo, hi), s3 = rangeSumD(o, lo, hi);
  float M = s0.x;
  vec3 sumX = s0.yzw, sumRest = s1.xyz;
  mat3 sumA = mat3(s1.w, s2.x, s2.y, s2.z, s2.w, s3.x, s3.y, s3.z, s3.w);
  float mg = stiff.y;
  if (ghosts > 0) {
    // Arithmetic series over the ghosts (csm::ghostSum1, ghostSum2).
    float q = float(ghosts);
    float g1 = mg * 0.5 * q * (q + 1.0), g2 = mg * q * (q + 1.0) * (2.0 * q + 1.0) / 6.0;
    M += mg * q;
    sumX -= g1 * D;
    sumRest -= g1 * d;
    sumA += outerProduct(g2 * D, d);
    addGhostShifts(field, ghosts, mg, d, sumX, sumA);
  }
  vec3 R0 = vec3(0.0), R1 = vec3(0.0), R2 = vec3(0.0), T = vec3(0.0);
  if (o.live) {
    vec3 c = sumX / M;
    vec3 cRest = sumRest / M;
    mat3 A = sumA - outerProduct(M * c, cRest);
    // The twist axis: the region's rest chord (ghosts continue the root segment).
    vec3 chord = readRest(int(o.a) + hi).xyz -
                 (ghosts > 0 ? rest0 - float(ghosts) * d : readRest(int(o.a) + lo).xyz);
    float chordLength = length(chord);
    vec3 axis = chordLength > 0.0 ? chord / chordLength : vec3(0.0);
    int iterations = max(1, P.rotationIterations);
    vec4 q = extractRotation(A, region.y, rotation[o.p], iterations, axis, st.twistStep);
    rotation[o.p] = q;
    mat3 R = quatToMat(q);
    R0 = R[0];
    R1 = R[1];
    R2 = R[2];
    T = c - R * cRest;
  }
  barrier();  // every slot has read its sums before the second scan writes over them

  // Scan 2: the regions' R and c - R c̄; each particle's goal from the regions lo..hi that hold
  // it (its own range), g = ((sum R) ȳ + sum (c - R c̄)) / |K|.
  v0 = vec4(R0, R1.x);
  v1 = vec4(R1.yz, R2.xy);
  v2 = vec4(R2.z, T);
  v3 = vec4(0.0);
  strandScan(o, v0, v1, v2, v3);
  s0 = rangeSumA(o, lo, hi);
  s1 = rangeSumB(o, lo, hi);
  s2 = rangeSumC(o, lo, hi);
  mat3 sumR = mat3(s0.xyz, vec3(s0.w, s1.xy), vec3(s1.zw, s2.x));
  vec3 sumT = s2.yzw;
  vec3 goal = origin + (sumR * yr + sumT) / float(hi - lo + 1);
  if (nearClamp) goal += readClampPull(o.p) * across;

  // Integration (eq. 2-3): x = x* + alpha (g - x*), v = (x - x_old) / h, damped.
  float h = st.h;
  float alpha = P.stiffnessModel == CSM_STIFFNESS_CALIBRATED ? min(1.0, stiff.x * h * h) : P.alpha;
  bool fixed_ = held;
  vec3 pull = alpha * (goal - xp);
  vec3 x = fixed_ ? xp : xp + pull;
  // The step's velocity from its own displacement (predict.glsl), not from rounded positions.
  vec3 v = !o.live ? vec3(0.0)
           : fixed_ ? (x - readPosition(o.p).xyz) / h
                    : (vPred + pull / h) * st.velocityKept;

#ifdef CSM_SWEEP
  barrier();  // the scan's slots are read; the sweep's state goes in
  shA[lid] = vec4(x, 1.0);
  shB[lid] = vec4(v, 0.0);
  shC[lid] = vec4(rest, 0.0);
  shD[lid] = vec4(0.0);
  barrier();
  sweepStrands(o, substep);
  x = shA[lid].xyz;
  v = shB[lid].xyz;
#endif
  if (o.live) {
    pos[o.p] = vec4(x, 1.0);
    vel[o.p] = vec4(v, 0.0);
  }
}
