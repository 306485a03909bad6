// Per-frame values shared by every render pass, one std140 block expanded from the list both
// languages share (frame_uniforms.glsl; render/frame_uniforms.h the C++ struct). Binding points
// from render/bindings.glsl, which the C++ passes include too (render/bindings.h).
#ifndef FRAME_GLSL
#define FRAME_GLSL
#include "render/bindings.glsl"
#include "render/frame_uniforms.glsl"
#include "sim/shared_constants.glsl"
// What each field holds: frame_uniforms.glsl.
layout(std140, binding = CSM_RENDER_FRAME_UNIFORMS) uniform FrameUniforms {
  CSM_FRAME_UNIFORMS(CSM_GLSL_FIELD)
};

// Integer hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering": PCG), so
// per-strand variation is the same on every driver and every run.
uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
float hashToUnit(uint h) { return float(h >> 8u) * exp2(-24.0); }  // 24 bits in [0, 1)
#endif  // FRAME_GLSL
