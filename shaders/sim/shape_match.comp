// Steps 3-5 of METHOD.md section 2, one invocation per strand: shape matching of every
// region, goals, and integration (shapeMatchStrand). The CPU twin: shapeMatchStrand
// (sim/solver/cpu_steps.cpp), on the regions sim/solver/stiffness.h builds for both.
//
// Why one invocation per strand: the region sums and the goal sums are prefix sums along
// the strand (Rivers & James 2007, FastLSM), and a strand has 8-25 particles (the paper's
// range; MAX_N is the longest strand of the groom). A sequential scan over so few elements
// costs one add per element, kept in private arrays (registers or L1 on a GPU, stack on
// llvmpipe), and needs no barrier, no shared memory and no padding: strands of any length
// are packed back to back (strandFirst), each invocation finds its own. A parallel segmented
// scan would spend log2(256) barrier rounds per work group to save 16 dependent adds. The
// per-region work (the rotation) is O(1) whatever w, since every sum is a difference of two
// prefix entries. Strands are taken in order of length (strandOrder) so that the invocations
// of a SIMD group run loops of the same length.
//
// Prefix sums are root-relative (x* - x*_root, x̄ - x̄_root) exactly as in CpuSolver, so the
// differences keep float precision (world coordinates would cancel 2 more digits in A).
// Regions come from regionTex (sim/solver/stiffness.h, built on the CPU): each particle's region
// [lo, hi] within the strand, which is also the range of regions containing it, its per-region
// mass (FastLSM) and 1 / J of its region.
#include "sim/common.glsl"

#ifndef MAX_N
#define MAX_N 32
#endif

layout(local_size_x = CSM_STRAND_GROUP) in;

// Inputs through texel fetches (on llvmpipe a vector gather, not a loop over the lanes).
// Each invocation reads its own particles' old positions before it writes them, and no
// other invocation writes them, so the fetches see the values of the previous pass.
layout(binding = CSM_TEX_POSITION) uniform samplerBuffer posTex;
layout(binding = CSM_TEX_REST) uniform samplerBuffer restTex;
layout(binding = CSM_TEX_PREDICTED) uniform samplerBuffer predTex;
layout(binding = CSM_TEX_VELOCITY) uniform samplerBuffer velTex;  // predict.comp's vPred
layout(binding = CSM_TEX_REGION) uniform samplerBuffer regionTex;
layout(binding = CSM_TEX_PARTICLE_CONSTANTS) uniform samplerBuffer constantsTex;  // y: the pull
layout(std430, binding = CSM_BIND_POSITION) writeonly buffer Position { vec4 pos[]; };
layout(std430, binding = CSM_BIND_VELOCITY) writeonly buffer Velocity { vec4 vel[]; };
layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_STRAND_ORDER) readonly buffer StrandOrder { uint strandOrder[]; };
layout(std430, binding = CSM_BIND_ROTATION) buffer Rotation { vec4 rotation[]; };
layout(std430, binding = CSM_BIND_STRAND_STIFFNESS) readonly buffer StrandStiffness {
  vec4 strandStiffness[];
};

uniform uint substep;

#define readRest(i) texelFetch(restTex, int(i))
#define CSM_CLAMP_PREDICTED(base, j) texelFetch(predTex, int(base) + (j)).xyz
#include "sim/clamp_field.glsl"

// Strand s: every region's sums, rotation and goal contribution, each particle's goal (paper eq.
// 1), and integration (eq. 2-3). The float twin of shapeMatchStrand in sim/solver/cpu_steps.cpp.
void shapeMatchStrand(uint s) {
  uint a = strandFirst[s];
  int n = int(strandFirst[s + 1u] - a);
  // MAX_N is the groom's longest strand (GpuSolver::reset rebuilds this pass when it grows);
  // the guard only keeps a failed rebuild from writing past the arrays.
  if (n <= 0 || n > MAX_N) return;
  int iterations = max(1, P.rotationIterations);
  vec3 origin = texelFetch(predTex, int(a)).xyz;
  vec3 rest0 = texelFetch(restTex, int(a)).xyz;
  Substep st = S[substep];
  vec4 stiff = strandStiffness[s];
  // Ghosts behind the root (sim/solver/stiffness.h): -j d at rest, -j D now, root-relative.
  float mg = stiff.y;
  vec3 d = n > 1 ? texelFetch(restTex, int(a) + 1).xyz - rest0 : vec3(0.0);
  vec3 D = mat3(st.head) * d;
  // The built-in end (clamp_field.glsl): the held particles and the ghosts take the free
  // strand's curvature at the clamp, continued.
  int pinned = pinnedOf(stiff);
  ClampField field = clampFieldOf(a, a, n, stiff, st.head);
  vec3 across = clampAcross(field, D);

  // Prefix sums over the strand's particles, weighted by per-region mass: m, m y, m ȳ, m y ȳᵀ
  // (y = x* - x*_root, ȳ = x̄ - x̄_root). Entry j holds the sum over particles [0, j).
  float prefM[MAX_N + 1];
  vec3 prefX[MAX_N + 1], prefRest[MAX_N + 1];
  mat3 prefA[MAX_N + 1];
  prefM[0] = 0.0;
  prefX[0] = vec3(0.0);
  prefRest[0] = vec3(0.0);
  prefA[0] = mat3(0.0);
  for (int j = 0; j < n; ++j) {
    float m = texelFetch(regionTex, int(a) + j).x;
    vec4 r = texelFetch(restTex, int(a) + j);  // w: its tau (clamp_field.glsl)
    vec3 yr = r.xyz - rest0;
    vec3 shift = j < pinned ? clampShift(field, r.w) : vec3(0.0);
    vec3 y = texelFetch(predTex, int(a) + j).xyz + shift - origin;
    prefM[j + 1] = prefM[j] + m;
    prefX[j + 1] = prefX[j] + m * y;
    prefRest[j + 1] = prefRest[j] + m * yr;
    prefA[j + 1] = prefA[j] + outerProduct(m * y, yr);
  }

  // Region k = particles [lo, hi]: centroids, A = sum m y ȳᵀ - M c c̄ᵀ, R from A; then the
  // prefix sums over regions of R_k and c_k - R_k c̄_k for the goals.
  mat3 prefR[MAX_N + 1];
  vec3 prefT[MAX_N + 1];
  prefR[0] = mat3(0.0);
  prefT[0] = vec3(0.0);
  for (int k = 0; k < n; ++k) {
    vec4 region = texelFetch(regionTex, int(a) + k);
    int ghosts = max(0, -int(region.z));
    // Clamped only so that bad region data can never index past the private arrays.
    int lo = clamp(int(region.z), 0, n - 1), hi = clamp(int(region.w), lo, n - 1);
    float M = prefM[hi + 1] - prefM[lo];
    vec3 sumX = prefX[hi + 1] - prefX[lo];
    vec3 sumRest = prefRest[hi + 1] - prefRest[lo];
    mat3 sumA = prefA[hi + 1] - prefA[lo];
    if (ghosts > 0) {
      // Arithmetic series over the ghosts (csm::ghostSum1, ghostSum2).
      float q = float(ghosts);
      float s1 = mg * 0.5 * q * (q + 1.0), s2 = mg * q * (q + 1.0) * (2.0 * q + 1.0) / 6.0;
      M += mg * q;
      sumX -= s1 * D;
      sumRest -= s1 * d;
      sumA += outerProduct(s2 * D, d);
      addGhostShifts(field, ghosts, mg, d, sumX, sumA);
    }
    vec3 c = sumX / M;
    vec3 cRest = sumRest / M;
    mat3 A = sumA - outerProduct(M * c, cRest);
    // The twist axis: the region's rest chord (ghosts continue the root segment).
    vec3 chord = texelFetch(restTex, int(a) + hi).xyz -
                 (ghosts > 0 ? rest0 - float(ghosts) * d : texelFetch(restTex, int(a) + lo).xyz);
    float chordLength = length(chord);
    vec3 axis = chordLength > 0.0 ? chord / chordLength : vec3(0.0);
    vec4 q = extractRotation(A, region.y, rotation[a + uint(k)], iterations, axis, st.twistStep);
    rotation[a + uint(k)] = q;
    mat3 R = quatToMat(q);
    prefR[k + 1] = prefR[k] + R;
    prefT[k + 1] = prefT[k] + (c - R * cRest);
  }

  // Goals (paper eq. 1) averaged over the regions containing each particle (the regions
  // lo..hi of its own range), g_i = ((sum R_k) ȳ_i + sum (c_k - R_k c̄_k)) / |K_i|, then
  // integration (eq. 2-3): x = x* + alpha (g - x*), v the step's own displacement over h, damped
  // (predict.glsl says why not (x - x_old) / h in float; the CPU's twin, in double, takes that).
  // alpha is the paper's, or min(1, k h^2) with the strand's calibrated rate k.
  float h = st.h;
  float keep = st.velocityKept;
  float alpha = P.stiffnessModel == CSM_STIFFNESS_CALIBRATED ? min(1.0, stiff.x * h * h) : P.alpha;
  for (int i = 0; i < n; ++i) {
    uint p = a + uint(i);
    vec4 region = texelFetch(regionTex, int(p));
    int lo = clamp(int(region.z), 0, n - 1), hi = clamp(int(region.w), lo, n - 1);
    vec3 yr = texelFetch(restTex, int(p)).xyz - rest0;
    vec3 goal = origin + ((prefR[hi + 1] - prefR[lo]) * yr + (prefT[hi + 1] - prefT[lo])) /
                             float(hi - lo + 1);
    // The clamp's pull, zero but where the region reaches behind the clamp.
    if (int(region.z) < pinned) goal += texelFetch(constantsTex, int(p)).y * across;
    vec3 xp = texelFetch(predTex, int(p)).xyz;
    bool fixed_ = heldAt(stiff, i, n);
    vec3 pull = alpha * (goal - xp);
    vec3 x = fixed_ ? xp : xp + pull;
    // The step's velocity from its own displacement (predict.glsl), not from rounded positions.
    vec3 v = fixed_ ? (x - texelFetch(posTex, int(p)).xyz) / h
                    : (texelFetch(velTex, int(p)).xyz + pull / h) * keep;
    pos[p] = vec4(x, 1.0);
    vel[p] = vec4(v, 0.0);
  }
}

void main() {
  uint id = globalIndex();
  if (id >= P.strands) return;
  shapeMatchStrand(strandOrder[id]);
}
