// The volume mode, once per frame (the CPU reference is csm::VolumeGrid::splat in
// sim/solver/volume.cpp), one invocation per particle: its share of strand length, and that length
// times its velocity, onto the 8 nodes around it (trilinear weights) of the grid fixed to the
// head where the frame starts. Fixed-point integer atomics: the sums do not depend on the
// order (the grid is cleared before). It also keeps the box of the nodes reached, for the
// node pass and predict.comp (volumeBox in common.glsl).
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

#include "sim/particle_reads.glsl"
layout(std430, binding = CSM_BIND_VOLUME_LENGTH) readonly buffer VolumeLength {
  float particleLength[];
};
layout(std430, binding = CSM_BIND_VOLUME_SUMS) buffer VolumeSums { int volumeSums[]; };

shared int reachedLow[3], reachedHigh[3];

void main() {
  uint i = globalIndex();
  uint lid = gl_LocalInvocationID.x;
  if (lid < 3u) {
    reachedLow[lid] = 0;
    reachedHigh[lid] = 0;
  }
  barrier();
  vec3 x = i < P.particles ? readPosition(int(i)).xyz : vec3(0.0);
  bool splats = i < P.particles && !any(isnan(x)) && !any(isinf(x));
  if (splats) {
    vec3 v = readVelocity(int(i)).xyz;
    ivec3 base;
    vec3 f;
    volumeLocate((P.volumeToHead * vec4(x, 1.0)).xyz, base, f);
    float len = particleLength[i] * kVolumeUnit;
    for (int c = 0; c < 8; ++c) {
      ivec3 d = ivec3(c & 1, (c >> 1) & 1, c >> 2);
      vec3 w3 = mix(1.0 - f, f, vec3(d));
      float wl = w3.x * w3.y * w3.z * len;
      uint k = 4u * volumeNode(base + d);
      atomicAdd(volumeSums[k], int(round(wl)));
      atomicAdd(volumeSums[k + 1u], int(round(wl * v.x)));
      atomicAdd(volumeSums[k + 2u], int(round(wl * v.y)));
      atomicAdd(volumeSums[k + 3u], int(round(wl * v.z)));
    }
    // The nodes reached, base to base + 1 (volumeBox's encoding), the group's first.
    ivec3 dims = ivec3(P.volumeDims);
    for (int a = 0; a < 3; ++a) {
      atomicMax(reachedLow[a], dims[a] - base[a]);
      atomicMax(reachedHigh[a], base[a] + 2);
    }
  }
  barrier();
  if (lid < 3u && reachedHigh[lid] > 0) {
    uint tail = 4u * uint(volumeNodes());
    atomicMax(volumeSums[tail + lid], reachedLow[lid]);
    atomicMax(volumeSums[tail + 4u + lid], reachedHigh[lid]);
  }
}
