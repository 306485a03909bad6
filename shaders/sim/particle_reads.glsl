// Per-particle reads of the step's passes (predict.glsl, strand_step.comp, strand_strain.comp)
// and the strand contacts' (grid_count, grid_scatter, candidates, contact_solve): positions,
// velocities, the rest shape, the regions, the per-particle constants (the contacts' inverse
// masses, the clamp's pull). Texel
// fetches of buffer textures by default (llvmpipe runs a texel fetch as one vector gather and a
// storage load as a loop over its SIMD lanes); with CSM_STORAGE_READS (a GPU: plain loads, one
// path through the caches) read-only storage blocks over the same buffers. The including pass
// may also write the positions and velocities through its own blocks: each invocation reads a
// particle of its strand before any of them writes one (a barrier between), and no other work
// group writes it.
#ifdef CSM_STORAGE_READS
layout(std430, binding = CSM_BIND_POSITION) readonly buffer PositionIn { vec4 positionIn[]; };
layout(std430, binding = CSM_BIND_VELOCITY) readonly buffer VelocityIn { vec4 velocityIn[]; };
layout(std430, binding = CSM_BIND_REST) readonly buffer RestIn { vec4 restIn[]; };
layout(std430, binding = CSM_BIND_REGION) readonly buffer RegionIn { vec4 regionIn[]; };
#define readPosition(i) positionIn[uint(i)]
#define readVelocity(i) velocityIn[uint(i)]
#define readRest(i) restIn[uint(i)]
#define readRegion(i) regionIn[uint(i)]
layout(std430, binding = CSM_BIND_PARTICLE_CONSTANTS) readonly buffer ParticleConstantsIn {
  vec2 particleConstantsIn[];
};
#define readInverseMass(i) particleConstantsIn[uint(i)].x
#define readClampPull(i) particleConstantsIn[uint(i)].y
#else
layout(binding = CSM_TEX_POSITION) uniform samplerBuffer posTex;
layout(binding = CSM_TEX_VELOCITY) uniform samplerBuffer velTex;
layout(binding = CSM_TEX_REST) uniform samplerBuffer restTex;
layout(binding = CSM_TEX_REGION) uniform samplerBuffer regionTex;
#define readPosition(i) texelFetch(posTex, int(i))
#define readVelocity(i) texelFetch(velTex, int(i))
#define readRest(i) texelFetch(restTex, int(i))
#define readRegion(i) texelFetch(regionTex, int(i))
layout(binding = CSM_TEX_PARTICLE_CONSTANTS) uniform samplerBuffer particleConstantsTex;
#define readInverseMass(i) texelFetch(particleConstantsTex, int(i)).x
#define readClampPull(i) texelFetch(particleConstantsTex, int(i)).y
#endif
