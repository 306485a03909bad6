// Reading the deep opacity maps (Yuksel & Keyser 2008, "Deep Opacity Maps"): light-space
// depth z0 of the nearest hair, then four layers of cumulative opacity starting at z0 and
// `spacing` apart. Layer k < 3 holds the opacity of the hair nearer than z0 + (k+1) spacing;
// layer 3 holds all of it. Transmittance is exp(-opacity), the opacity interpolated
// linearly between the layer boundaries.
#ifndef DOM_GLSL
#define DOM_GLSL
#include "render/frame.glsl"

layout(binding = LIGHT_DEPTH_UNIT) uniform sampler2D uLightDepth;
layout(binding = OPACITY_LAYERS_UNIT) uniform sampler2D uOpacityLayers;
layout(binding = HEAD_SHADOW_UNIT) uniform sampler2DShadow uHeadShadow;

// Opacity in front of a point `t` layer spacings behind z0: piecewise linear through
// (0, 0), (1, L0), (2, L1), (3, L2) and reaching L3 at 4.
float layeredOpacity(vec4 layers, float t) {
  if (t <= 0.0) return 0.0;
  if (t < 1.0) return layers.x * t;
  if (t < 2.0) return mix(layers.x, layers.y, t - 1.0);
  if (t < 3.0) return mix(layers.y, layers.z, t - 2.0);
  return mix(layers.z, layers.w, min(t - 3.0, 1.0));
}

// Light reaching `worldPos` through the hair, 0..1. The four texels around the point are
// each evaluated against their own z0 and blended bilinearly: filtering z0 itself would
// average depths across silhouettes and light the hair behind them.
float hairTransmittance(vec3 worldPos) {
  if (uHeadColor.a < 0.5) return 1.0;
  vec3 lp = (uLightViewProj * vec4(worldPos, 1.0)).xyz * 0.5 + 0.5;
  if (any(lessThan(lp, vec3(0.0))) || any(greaterThan(lp, vec3(1.0)))) return 1.0;
  float size = uLightRange.y;
  vec2 st = lp.xy * size - 0.5;
  ivec2 base = ivec2(floor(st));
  vec2 f = st - vec2(base);
  float unitsPerLayer = uLightRange.x / uSpecStrength.w;  // light depth -> layer spacings
  float opacity = 0.0;
  for (int k = 0; k < 4; ++k) {
    ivec2 o = ivec2(k & 1, k >> 1);
    ivec2 texel = clamp(base + o, ivec2(0), ivec2(int(size) - 1));
    float z0 = texelFetch(uLightDepth, texel, 0).r;
    float a = z0 < 1.0 ? layeredOpacity(texelFetch(uOpacityLayers, texel, 0),
                                        (lp.z - z0) * unitsPerLayer)
                       : 0.0;
    float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
    opacity += w * a;
  }
  return exp(-opacity);
}

// The head's shadow on the hair and on itself: a depth map of the spheres' back faces
// (so lit faces never shadow themselves), compared with hardware 2x2 filtering.
float headVisibility(vec3 worldPos) {
  if (uHeadColor.a < 0.5) return 1.0;
  vec3 lp = (uLightViewProj * vec4(worldPos, 1.0)).xyz * 0.5 + 0.5;
  if (any(lessThan(lp, vec3(0.0))) || any(greaterThan(lp, vec3(1.0)))) return 1.0;
  return texture(uHeadShadow, lp);
}
#endif  // DOM_GLSL
