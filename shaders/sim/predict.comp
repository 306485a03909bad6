// Steps 1-2 of METHOD.md section 2.2, one invocation per particle (predict.glsl): the per-strand
// path's first pass (strand_step.comp does this inside its own).
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

#include "sim/particle_reads.glsl"
layout(std430, binding = CSM_BIND_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_BIND_PARTICLE_STRAND) readonly buffer ParticleStrand {
  uint particleStrand[];
};
layout(std430, binding = CSM_BIND_PREDICTED) writeonly buffer Predicted { vec4 pred[]; };
layout(std430, binding = CSM_BIND_STRAND_STIFFNESS) readonly buffer StrandStiffness {
  vec4 strandStiffness[];
};


uniform uint substep;

#include "sim/predict.glsl"

void main() {
  uint i = globalIndex();
  if (i >= P.particles) return;
  uint s = particleStrand[i];
  pred[i] = vec4(predictParticle(i, strandFirst[s], strandFirst[s + 1u], int(strandStiffness[2u * s].z),
                                 S[substep]),
                 1.0);
}
