// Step 1-2 of DESIGN.md section 1, one invocation per particle: kinematic roots follow the
// head; free particles get gravity and wind drag, and move to x* = x + h (v + h f / m). The velocity itself is not written: integration
// (at the end of shape_match.comp) recomputes it from the positions, as the CPU solver does.
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

layout(std430, binding = CSM_BIND_VOLUME_SUMS) readonly buffer VolumeSums { int volumeSums[]; };
layout(std430, binding = CSM_BIND_VOLUME_EXCESS) readonly buffer VolumeExcess {
  float volumeExcess[];
};

uniform uint substep;

// The volume fraction over what is allowed at head-frame x (csm::VolumeGrid::excessAt).
float excessAt(vec3 x) {
  ivec3 base;
  vec3 f;
  volumeLocate(x, base, f);
  float excess = 0.0;
  for (int c = 0; c < 8; ++c) {
    ivec3 d = ivec3(c & 1, (c >> 1) & 1, c >> 2);
    vec3 a = mix(1.0 - f, f, vec3(d));
    excess += a.x * a.y * a.z * volumeExcess[volumeNode(base + d)];
  }
  return excess;
}

// The volume mode (csm::VolumeGrid::velocityChange): toward the hair's mean velocity here, and
// down the gradient of the volume fraction over what is allowed (central differences half a
// cell apart: continuous across cell faces).
vec3 volumeVelocityChange(vec3 xWorld, vec3 v, float h) {
  vec3 x = (P.volumeToHead * vec4(xWorld, 1.0)).xyz;
  ivec3 base;
  vec3 f;
  volumeLocate(x, base, f);
  float len = 0.0;
  vec3 momentum = vec3(0.0);
  for (int c = 0; c < 8; ++c) {
    ivec3 d = ivec3(c & 1, (c >> 1) & 1, c >> 2);
    vec3 a = mix(1.0 - f, f, vec3(d));
    float w = a.x * a.y * a.z;
    uint k = 4u * volumeNode(base + d);
    len += w * float(volumeSums[k]);
    momentum += w * vec3(volumeSums[k + 1u], volumeSums[k + 2u], volumeSums[k + 3u]);
  }
  vec3 dv = vec3(0.0);
  if (len > 0.0) dv += (1.0 - exp(-P.volume.x * h)) * (momentum / len - v);
  if (P.volume.y > 0.0) {
    float offset = 0.5 * P.volumeOrigin.w;
    vec3 gradient;
    for (int axis = 0; axis < 3; ++axis) {
      vec3 e = vec3(0.0);
      e[axis] = offset;
      gradient[axis] = (excessAt(x + e) - excessAt(x - e)) / (2.0 * offset);
    }
    dv -= h * P.volume.y * mat3(P.volumeToWorld) * gradient;
  }
  return dv;
}

void main() {
  uint i = globalIndex();
  if (i >= P.counts.x) return;
  uint s = particleStrand[i];
  uint a = strandFirst[s], b = strandFirst[s + 1u];
  Substep st = S[substep];
  vec4 r = texelFetch(restTex, int(i));
  if (int(i - a) < int(strandStiffness[s].z)) {
    pred[i] = vec4((st.head * vec4(r.xyz, 1.0)).xyz, 1.0);
    return;
  }
  float h = st.time.y;
  vec3 x = texelFetch(posTex, int(i)).xyz;
  vec3 v = texelFetch(velTex, int(i)).xyz;
  vec3 acc = P.gravity.xyz;
  if (P.flags.z != 0u) {
    // Drag acts on the wind across the strand, not along it; implicit in the velocity
    // (c / (1 + h c) instead of c), as CpuSolver::windDrag.
    vec3 d = texelFetch(posTex, int(min(i + 1u, b - 1u))).xyz -
             texelFetch(posTex, int(max(i, a + 1u) - 1u)).xyz;
    float len = length(d);
    vec3 t = len > 1e-12 ? d / len : vec3(0.0);
    vec3 rel = windVelocity(x, st.time.x) - v;
    float c = P.misc.y;
    acc += c / (1.0 + h * c) * (rel - dot(rel, t) * t);
  }
  if (P.volumeDims.w != 0u) v += volumeVelocityChange(x, v, h);
  v += h * acc;
  pred[i] = vec4(x + h * v, 1.0);
}
