// The volume mode, once per frame after volume_splat.comp (the CPU reference is the end of
// csm::VolumeGrid::splat in sim/volume.cpp), one invocation per node: its volume fraction
// over what is allowed there (the larger of collision.volume_fraction and what the rest groom
// packs), which predict.comp's push interpolates.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(std430, binding = CSM_BIND_VOLUME_SUMS) readonly buffer VolumeSums { int volumeSums[]; };
layout(std430, binding = CSM_BIND_VOLUME_REST) readonly buffer VolumeRest { float volumeRest[]; };
layout(std430, binding = CSM_BIND_VOLUME_EXCESS) writeonly buffer VolumeExcess {
  float volumeExcess[];
};

void main() {
  uint node = globalIndex();
  if (node >= P.volumeDims.x * P.volumeDims.y * P.volumeDims.z) return;
  float allowed = max(P.volume.z, volumeRest[node]);
  volumeExcess[node] = max(0.0, float(volumeSums[4u * node]) * P.volume.w - allowed);
}
