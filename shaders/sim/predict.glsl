// Steps 1-2 of METHOD.md section 2.2 for one particle, shared by predict.comp (one invocation
// per particle) and strand_step.comp (a strand's particles in one work group): kinematic roots
// follow the head; free particles get gravity and wind drag, and move to x* = x + h (v + h f / m).
// The velocity itself is not written: integration (shape matching's last step) recomputes it
// from the positions, as the CPU solver does (its twin: predictParticle,
// sim/solver/cpu_steps.cpp). The including pass includes particle_reads.glsl and declares
// strandStiffness.
#include "sim/wind.glsl"

// The volume's nodes (volume_field.comp) and the box the splat reached (volumeBox).
#ifdef CSM_STORAGE_READS
layout(std430, binding = CSM_BIND_VOLUME_FIELD) readonly buffer VolumeFieldIn {
  vec4 volumeFieldIn[];
};
layout(std430, binding = CSM_BIND_VOLUME_SUMS) readonly buffer VolumeSumsIn { ivec4 volumeSumsIn[]; };
#define readVolumeField(k) volumeFieldIn[uint(k)]
#define readVolumeBox(low, high) \
  volumeBoxOf(volumeSumsIn[volumeNodes()], volumeSumsIn[volumeNodes() + 1], low, high)
#else
layout(binding = CSM_TEX_VOLUME_FIELD) uniform samplerBuffer volumeFieldTex;
layout(binding = CSM_TEX_VOLUME_SUMS) uniform isamplerBuffer volumeSumsTex;
#define readVolumeField(k) texelFetch(volumeFieldTex, int(k))
#define readVolumeBox(low, high) volumeBox(volumeSumsTex, low, high)
#endif

// The volume mode (csm::VolumeGrid::velocityChange): toward the hair's mean velocity here, and
// down the gradient of the volume fraction over what is allowed, both interpolated from the
// 8 nodes around (volume_field.comp).
vec3 volumeVelocityChange(vec3 xWorld, vec3 v, float h) {
  ivec3 base;
  vec3 f;
  volumeLocate((P.volumeToHead * vec4(xWorld, 1.0)).xyz, base, f);
  // Nodes outside the box the splat reached hold 0 (volume_field.comp leaves them).
  ivec3 low, high;
  readVolumeBox(low, high);
  vec4 sums = vec4(0.0);
  vec3 gradient = vec3(0.0);
  for (int c = 0; c < 8; ++c) {
    ivec3 d = ivec3(c & 1, (c >> 1) & 1, c >> 2);
    vec3 a = mix(1.0 - f, f, vec3(d));
    float w = a.x * a.y * a.z;
    ivec3 n = base + d;
    bool inBox = all(greaterThanEqual(n, low)) && all(lessThanEqual(n, high));
    int k = 2 * int(volumeNode(n));
    vec4 s = readVolumeField(k), g = readVolumeField(k + 1);
    sums += w * (inBox ? s : vec4(0.0));
    gradient += w * (inBox ? g.xyz : vec3(0.0));
  }
  vec3 dv = vec3(0.0);
  if (sums.w > 0.0) dv += (1.0 - exp(-P.volumeFriction * h)) * (sums.xyz / sums.w - v);
  if (P.volumeStiffness > 0.0) dv -= h * P.volumeStiffness * mat3(P.volumeToWorld) * gradient;
  return dv;
}

// x* of particle i of the strand [a, b), held by the head or not (heldAt), and the
// velocity that moved it there (vPred: x* = x + h vPred; zero for a held particle). The step's
// velocity is vPred plus the goals' pull over h, not (x - x_old) / h: at hundreds of steps a
// frame a step moves a particle ~10 um and its float position rounds by ~0.02 um, which that
// difference would carry into the velocity, step after step (METHOD.md section 4.3).
vec3 predictParticle(uint i, uint a, uint b, bool held, Substep st, out vec3 vPred) {
  vec4 r = readRest(i);
  vPred = vec3(0.0);
  if (held) return (st.head * vec4(r.xyz, 1.0)).xyz;
  float h = st.h;
  vec3 x = readPosition(i).xyz;
  vec3 v = readVelocity(i).xyz;
  vec3 acc = P.gravity;
  if (P.windOn != 0u) {
    // Drag acts on the wind across the strand, not along it; implicit in the velocity
    // (c / (1 + h c) instead of c), as predictParticle in sim/solver/cpu_steps.cpp.
    vec3 d = readPosition(min(i + 1u, b - 1u)).xyz -
             readPosition(max(i, a + 1u) - 1u).xyz;
    float len = length(d);
    vec3 t = len > 1e-12 ? d / len : vec3(0.0);
    vec3 rel = windVelocity(x, st.stepStart) - v;
    float c = P.windDrag;
    acc += c / (1.0 + h * c) * (rel - dot(rel, t) * t);
  }
  if (P.volumeForces != 0u) v += volumeVelocityChange(x, v, h);
  v += h * acc;
  vPred = v;
  return x + h * v;
}
