// Steps 1-2 of METHOD.md section 2.2, one invocation per particle: kinematic roots follow the
// head; free particles get gravity and wind drag, and move to x* = x + h (v + h f / m). The velocity itself is not written: integration
// (at the end of shape_match.comp) recomputes it from the positions, as the CPU solver does
// (its twin: CpuSolver's predict step, sim/solver/cpu_solver.cpp).
#include "sim/common.glsl"
#include "sim/wind.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

// Read through texel fetches: on llvmpipe a vector gather instead of a loop over the lanes.
layout(binding = CSM_TEX_POSITION) uniform samplerBuffer posTex;
layout(binding = CSM_TEX_VELOCITY) uniform samplerBuffer velTex;
layout(binding = CSM_TEX_REST) uniform samplerBuffer restTex;
layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_PREDICTED) writeonly buffer Predicted { vec4 pred[]; };
layout(std430, binding = CSM_BIND_STRAND_STIFFNESS) readonly buffer StrandStiffness {
  vec4 strandStiffness[];
};

layout(binding = CSM_TEX_VOLUME_FIELD) uniform samplerBuffer volumeFieldTex;
layout(binding = CSM_TEX_VOLUME_SUMS) uniform isamplerBuffer volumeSumsTex;

uniform uint substep;

// The volume mode (csm::VolumeGrid::velocityChange): toward the hair's mean velocity here, and
// down the gradient of the volume fraction over what is allowed, both interpolated from the
// 8 nodes around (volume_field.comp).
vec3 volumeVelocityChange(vec3 xWorld, vec3 v, float h) {
  ivec3 base;
  vec3 f;
  volumeLocate((P.volumeToHead * vec4(xWorld, 1.0)).xyz, base, f);
  // Nodes outside the box the splat reached hold 0 (volume_field.comp leaves them).
  ivec3 low, high;
  volumeBox(volumeSumsTex, low, high);
  vec4 sums = vec4(0.0);
  vec3 gradient = vec3(0.0);
  for (int c = 0; c < 8; ++c) {
    ivec3 d = ivec3(c & 1, (c >> 1) & 1, c >> 2);
    vec3 a = mix(1.0 - f, f, vec3(d));
    float w = a.x * a.y * a.z;
    ivec3 n = base + d;
    bool inBox = all(greaterThanEqual(n, low)) && all(lessThanEqual(n, high));
    int k = 2 * int(volumeNode(n));
    vec4 s = texelFetch(volumeFieldTex, k), g = texelFetch(volumeFieldTex, k + 1);
    sums += w * (inBox ? s : vec4(0.0));
    gradient += w * (inBox ? g.xyz : vec3(0.0));
  }
  vec3 dv = vec3(0.0);
  if (sums.w > 0.0) dv += (1.0 - exp(-P.volumeFriction * h)) * (sums.xyz / sums.w - v);
  if (P.volumeStiffness > 0.0) dv -= h * P.volumeStiffness * mat3(P.volumeToWorld) * gradient;
  return dv;
}

void main() {
  uint i = globalIndex();
  if (i >= P.particles) return;
  uint s = particleStrand[i];
  uint a = strandFirst[s], b = strandFirst[s + 1u];
  Substep st = S[substep];
  vec4 r = texelFetch(restTex, int(i));
  if (int(i - a) < int(strandStiffness[s].z)) {
    pred[i] = vec4((st.head * vec4(r.xyz, 1.0)).xyz, 1.0);
    return;
  }
  float h = st.h;
  vec3 x = texelFetch(posTex, int(i)).xyz;
  vec3 v = texelFetch(velTex, int(i)).xyz;
  vec3 acc = P.gravity;
  if (P.windOn != 0u) {
    // Drag acts on the wind across the strand, not along it; implicit in the velocity
    // (c / (1 + h c) instead of c), as CpuSolver::windDrag.
    vec3 d = texelFetch(posTex, int(min(i + 1u, b - 1u))).xyz -
             texelFetch(posTex, int(max(i, a + 1u) - 1u)).xyz;
    float len = length(d);
    vec3 t = len > 1e-12 ? d / len : vec3(0.0);
    vec3 rel = windVelocity(x, st.stepStart) - v;
    float c = P.windDrag;
    acc += c / (1.0 + h * c) * (rel - dot(rel, t) * t);
  }
  if (P.volumeForces != 0u) v += volumeVelocityChange(x, v, h);
  v += h * acc;
  pred[i] = vec4(x + h * v, 1.0);
}
