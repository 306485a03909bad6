// Per-frame values shared by every render pass, one std140 block (render/hair_renderer.cpp
// FrameUniforms mirrors it field for field). Binding points from render/bindings.glsl, which
// the C++ passes include too (render/bindings.h).
#ifndef FRAME_GLSL
#define FRAME_GLSL
#include "render/bindings.glsl"
layout(std140, binding = CSM_RENDER_FRAME_UNIFORMS) uniform FrameUniforms {
  mat4 uViewProj;
  mat4 uLightViewProj;  // world -> light clip space (orthographic)
  mat4 uHeadRotation;   // the head pose's rotation (the strands' frames turn with it)
  vec4 uEye;            // xyz: camera position
  vec4 uLightDir;       // xyz: direction the light travels (unit); w: intensity
  vec4 uLightColor;     // rgb; a: ambient
  vec4 uRootColor;      // rgb; a: per-strand colour variation
  vec4 uTipColor;       // rgb; a: opacity of one strand
  vec4 uSpecShift;      // x, y: primary and secondary shift; z, w: their exponents
  vec4 uSpecStrength;   // x, y: primary and secondary strength; z: strand width (px);
                        // w: deep opacity layer spacing (m)
  vec4 uHeadColor;      // rgb; a: 1 when shadows are on
  vec4 uBackground;     // rgb
  vec4 uViewport;       // width, height, 1/width, 1/height
  vec4 uLightRange;     // x: metres per unit of light depth; y: map size; z: 1/size;
                        // w: a texel's side (m)
  vec4 uChildren;       // x: children's distance from their guide at the root (m); y: clump,
                        // the share of it closed at the tip; z: opacity scale of the shadow
                        // passes (1 / share of strands drawn); w: noise (m)
  vec4 uChildren2;      // x: length variation; y: share of children between two guides;
                        // z: children each child drawn into the opacity maps stands for
  ivec4 uCounts;        // x: subdivision; y: children per guide; z: a child's step in its
                        // guide's spline points; w: strand flags (1 groom colours, 2 thickness)
  ivec4 uCounts2;       // x: spline points; y: head spheres
  vec4 uWidth;          // x: strand width on screen (m; 0: uSpecStrength.z pixels instead);
                        // y: pixels per metre at view depth 1; z: the width (m) a strand
                        // stands for in the shadow maps
};

const float kPi = 3.14159265358979;

// Integer hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering": PCG), so
// per-strand variation is the same on every driver and every run.
uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
float hashToUnit(uint h) { return float(h >> 8u) * (1.0 / 16777216.0); }
#endif  // FRAME_GLSL
