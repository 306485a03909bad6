// Reading the deep opacity maps (Yuksel & Keyser 2008, "Deep Opacity Maps"): light-space
// depth z0 of the nearest hair, then four layers of cumulative opacity starting at z0 and
// `spacing` apart. Layer k < 3 holds the opacity of the hair nearer than z0 + (k+1) spacing;
// layer 3 holds all of it. Transmittance is exp(-opacity), the opacity interpolated
// linearly between the layer boundaries.
#ifndef DOM_GLSL
#define DOM_GLSL
#include "render/frame.glsl"

layout(binding = CSM_RENDER_LIGHT_DEPTH_UNIT) uniform sampler2D uLightDepth;
layout(binding = CSM_RENDER_OPACITY_LAYERS_UNIT) uniform sampler2D uOpacityLayers;
layout(binding = CSM_RENDER_HEAD_SHADOW_UNIT) uniform sampler2DShadow uHeadShadow;

// Opacity in front of a point `t` layer spacings behind z0: piecewise linear through
// (0, 0), (1, L0), (2, L1), (3, L2) and reaching L3 at 4.
float layeredOpacity(vec4 layers, float t) {
  if (t <= 0.0) return 0.0;
  if (t < 1.0) return layers.x * t;
  if (t < 2.0) return mix(layers.x, layers.y, t - 1.0);
  if (t < 3.0) return mix(layers.y, layers.z, t - 2.0);
  return mix(layers.z, layers.w, min(t - 3.0, 1.0));
}

// Opacity in front of light-space point `lp` (xy in [0,1], z the light depth). The four
// texels around the point are each evaluated against their own z0 and blended bilinearly:
// filtering z0 itself would average depths across silhouettes and light the hair behind them.
float deepOpacity(vec3 lp) {
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
  return opacity;
}

bool inLightBox(vec3 lp) {
  return all(greaterThanEqual(lp, vec3(0.0))) && all(lessThanEqual(lp, vec3(1.0)));
}

// Light reaching `worldPos` through the hair, 0..1.
float hairTransmittance(vec3 worldPos) {
  if (uHeadColor.a < 0.5) return 1.0;
  vec3 lp = (uLightViewProj * vec4(worldPos, 1.0)).xyz * 0.5 + 0.5;
  return inLightBox(lp) ? exp(-deepOpacity(lp)) : 1.0;
}

// The same over a wider footprint (four bilinear lookups 1.5 texels apart), for surfaces
// that catch the shadow of single strands: the head. The maps draw a strand one texel
// wide, and its shadow on a smooth surface would otherwise show the texel staircase.
float hairTransmittanceSoft(vec3 worldPos) {
  if (uHeadColor.a < 0.5) return 1.0;
  vec3 lp = (uLightViewProj * vec4(worldPos, 1.0)).xyz * 0.5 + 0.5;
  if (!inLightBox(lp)) return 1.0;
  float d = 0.75 * uLightRange.z;
  float opacity = deepOpacity(lp + vec3(-d, -d, 0.0)) + deepOpacity(lp + vec3(d, -d, 0.0)) +
                  deepOpacity(lp + vec3(-d, d, 0.0)) + deepOpacity(lp + vec3(d, d, 0.0));
  return exp(-0.25 * opacity);
}

// The head's shadow on the hair and on itself: a depth map of the spheres' back faces
// (so lit faces never shadow themselves), compared with hardware 2x2 filtering.
float headVisibility(vec3 worldPos) {
  if (uHeadColor.a < 0.5) return 1.0;
  vec3 lp = (uLightViewProj * vec4(worldPos, 1.0)).xyz * 0.5 + 0.5;
  return inLightBox(lp) ? texture(uHeadShadow, lp) : 1.0;
}
// The same over a disc about three texels wide (eight filtered taps): the head's own shadow
// on itself, whose edges in the eye sockets, under the nose and the lips would otherwise show
// the map's texels.
float headVisibilitySoft(vec3 worldPos) {
  if (uHeadColor.a < 0.5) return 1.0;
  vec3 lp = (uLightViewProj * vec4(worldPos, 1.0)).xyz * 0.5 + 0.5;
  if (!inLightBox(lp)) return 1.0;
  const vec2 kTaps[8] = vec2[8](vec2(-0.61, 0.25), vec2(0.27, 0.69), vec2(0.78, -0.08),
                                vec2(-0.18, -0.72), vec2(-1.35, -0.47), vec2(0.52, 1.38),
                                vec2(1.31, -0.89), vec2(-0.85, 1.12));
  float sum = 0.0;
  for (int i = 0; i < 8; ++i)
    sum += texture(uHeadShadow, lp + vec3(kTaps[i] * 1.1 * uLightRange.z, 0.0));
  return sum / 8.0;
}
#endif  // DOM_GLSL
