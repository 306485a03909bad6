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
// The velocity that moved each free particle to x* (predict.glsl), for shape_match.comp.
layout(std430, binding = CSM_BIND_VELOCITY) writeonly buffer Velocity { vec4 vel[]; };
layout(std430, binding = CSM_BIND_STRAND_STIFFNESS) readonly buffer StrandStiffness {
  vec4 strandStiffness[];
};


uniform uint substep;

#include "sim/predict.glsl"

void main() {
  uint i = globalIndex();
  if (i >= P.particles) return;
  uint s = particleStrand[i];
  uint a = strandFirst[s], b = strandFirst[s + 1u];
  bool held = heldAt(strandStiffness[s], int(i - a), int(b - a));
  vec3 vPred;
  pred[i] = vec4(predictParticle(i, a, b, held, S[substep], vPred), 1.0);
  // Each invocation has read its own velocity above; a held particle's is left for
  // shape_match.comp, which takes it from the head's motion.
  if (!held) vel[i] = vec4(vPred, 0.0);
}
