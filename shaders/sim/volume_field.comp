// The volume mode, once per frame after volume_splat.comp (the CPU reference is the end of
// csm::VolumeGrid::splat in sim/solver/volume.cpp), one invocation per node of the box the splat
// reached (volumeBox; an indirect dispatch sized by volume_dispatch.comp: small hair in a
// large grid pays for its own nodes, not the grid's): what predict.comp
// interpolates at each particle, so that it reads 8 nodes' fields and no more:
//  - the node's sums as floats, length times velocity then length (the hair's mean velocity
//    is their interpolated ratio);
//  - the gradient of the volume fraction over what is allowed (the larger of
//    collision.volume_fraction and what the rest groom packs), by central differences
//    between the neighbouring nodes, one-sided on the grid's faces.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

#ifdef CSM_STORAGE_READS
layout(std430, binding = CSM_BIND_VOLUME_SUMS) readonly buffer VolumeSumsIn { ivec4 sumsIn[]; };
layout(std430, binding = CSM_BIND_VOLUME_REST) readonly buffer VolumeRestIn {
  float restFractionIn[];
};
#define readSums(node) sumsIn[uint(node)]
#define readRestFraction(node) restFractionIn[uint(node)]
#else
layout(binding = CSM_TEX_VOLUME_SUMS) uniform isamplerBuffer sumsTex;
layout(binding = CSM_TEX_VOLUME_REST) uniform samplerBuffer restFractionTex;
#define readSums(node) texelFetch(sumsTex, int(node))
#define readRestFraction(node) texelFetch(restFractionTex, int(node)).x
#endif
layout(std430, binding = CSM_BIND_VOLUME_FIELD) writeonly buffer VolumeField {
  vec4 volumeField[];
};

float excessAt(uint node) {
  float allowed = max(P.volumeAllowed, readRestFraction(node));
  return max(0.0, float(readSums(node).x) * P.volumePerUnit - allowed);
}

void main() {
  ivec3 dims = ivec3(P.volumeDims);
  ivec3 low, high;
  ivec3 box = volumeBoxOf(readSums(volumeNodes()), readSums(volumeNodes() + 1), low, high);
  uint k = globalIndex();
  if (k >= uint(box.x * box.y * box.z)) return;
  ivec3 n = low + ivec3(k % uint(box.x), (k / uint(box.x)) % uint(box.y), k / uint(box.x * box.y));
  uint node = volumeNode(n);
  vec3 gradient;
  for (int axis = 0; axis < 3; ++axis) {
    ivec3 below = n, above = n;
    below[axis] = max(n[axis] - 1, 0);
    above[axis] = min(n[axis] + 1, dims[axis] - 1);
    gradient[axis] = (excessAt(volumeNode(above)) - excessAt(volumeNode(below))) /
                     (float(above[axis] - below[axis]) * P.volumeCell);
  }
  ivec4 sums = readSums(node);
  volumeField[2u * node] = vec4(vec3(sums.yzw), float(sums.x));
  volumeField[2u * node + 1u] = vec4(gradient, 0.0);
}
