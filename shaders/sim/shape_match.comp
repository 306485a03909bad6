// Steps 3-5 of DESIGN.md section 1, one invocation per strand: shape matching of every
// region, goals, and integration.
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
layout(std430, binding = CSM_BIND_POSITION) writeonly buffer Position { vec4 pos[]; };
layout(std430, binding = CSM_BIND_VELOCITY) writeonly buffer Velocity { vec4 vel[]; };
layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_STRAND_ORDER) readonly buffer StrandOrder { uint strandOrder[]; };
layout(std430, binding = CSM_BIND_ROTATION) buffer Rotation { vec4 rotation[]; };

uniform uint substep;

void main() {
  uint id = globalIndex();
  if (id >= P.counts.y) return;
  uint s = strandOrder[id];
  uint a = strandFirst[s];
  int n = int(strandFirst[s + 1u] - a);
  // MAX_N is the groom's longest strand (GpuSolver::reset rebuilds this pass when it grows);
  // the guard only keeps a failed rebuild from writing past the arrays.
  if (n <= 0 || n > MAX_N) return;
  int w = max(1, P.ints.y);
  int iterations = max(1, P.ints.z);
  vec3 origin = texelFetch(predTex, int(a)).xyz;
  vec3 rest0 = texelFetch(restTex, int(a)).xyz;

  // Prefix sums over the strand's particles: mass, m y, m ȳ, m y ȳᵀ (y = x* - x*_root,
  // ȳ = x̄ - x̄_root). Entry j holds the sum over particles [0, j).
  float prefM[MAX_N + 1];
  vec3 prefX[MAX_N + 1], prefRest[MAX_N + 1];
  mat3 prefA[MAX_N + 1];
  prefM[0] = 0.0;
  prefX[0] = vec3(0.0);
  prefRest[0] = vec3(0.0);
  prefA[0] = mat3(0.0);
  for (int j = 0; j < n; ++j) {
    vec4 r = texelFetch(restTex, int(a) + j);
    float m = r.w;
    vec3 y = texelFetch(predTex, int(a) + j).xyz - origin;
    vec3 yr = r.xyz - rest0;
    prefM[j + 1] = prefM[j] + m;
    prefX[j + 1] = prefX[j] + m * y;
    prefRest[j + 1] = prefRest[j] + m * yr;
    prefA[j + 1] = prefA[j] + outerProduct(m * y, yr);
  }

  // Region k = particles [k-w, k+w]: centroids, A = sum m y ȳᵀ - M c c̄ᵀ, R from A; then the
  // prefix sums over regions of R_k and c_k - R_k c̄_k for the goals.
  mat3 prefR[MAX_N + 1];
  vec3 prefT[MAX_N + 1];
  prefR[0] = mat3(0.0);
  prefT[0] = vec3(0.0);
  for (int k = 0; k < n; ++k) {
    int lo = max(0, k - w), hi = min(n - 1, k + w);
    float M = prefM[hi + 1] - prefM[lo];
    vec3 c = (prefX[hi + 1] - prefX[lo]) / M;
    vec3 cRest = (prefRest[hi + 1] - prefRest[lo]) / M;
    mat3 A = (prefA[hi + 1] - prefA[lo]) - outerProduct(M * c, cRest);
    vec4 q = extractRotation(A, rotation[a + uint(k)], iterations);
    rotation[a + uint(k)] = q;
    mat3 R = quatToMat(q);
    prefR[k + 1] = prefR[k] + R;
    prefT[k + 1] = prefT[k] + (c - R * cRest);
  }

  // Goals (paper eq. 1) averaged over the regions containing each particle,
  // g_i = ((sum R_k) ȳ_i + sum (c_k - R_k c̄_k)) / |K_i|, then integration (eq. 2-3):
  // x = x* + alpha (g - x*), v = (x - x_old) / h, damped.
  Substep st = S[substep];
  float h = st.time.y;
  float keep = st.time.w;
  float alpha = P.stepping.x;
  int pinned = P.ints.x;
  for (int i = 0; i < n; ++i) {
    uint p = a + uint(i);
    int lo = max(0, i - w), hi = min(n - 1, i + w);
    vec3 yr = texelFetch(restTex, int(p)).xyz - rest0;
    vec3 goal = origin + ((prefR[hi + 1] - prefR[lo]) * yr + (prefT[hi + 1] - prefT[lo])) /
                             float(hi - lo + 1);
    vec3 xp = texelFetch(predTex, int(p)).xyz;
    bool fixed_ = i < pinned;
    vec3 x = fixed_ ? xp : xp + alpha * (goal - xp);
    vec3 v = (x - texelFetch(posTex, int(p)).xyz) / h;
    if (!fixed_) v *= keep;
    pos[p] = vec4(x, 1.0);
    vel[p] = vec4(v, 0.0);
  }
}
