// Linear HDR -> display. Each sample is tone-mapped before the samples are averaged, so a
// bright highlight on a strand thinner than a pixel antialiases as well as the dark hair
// around it (resolving first would let the highlight dominate the pixel). Then the sRGB
// transfer curve and a deterministic dither against banding in the backdrop.
#include "render/frame.glsl"

#if SAMPLES > 1
layout(binding = CSM_RENDER_RESOLVED_UNIT) uniform sampler2DMS uFrame;
#else
layout(binding = CSM_RENDER_RESOLVED_UNIT) uniform sampler2D uFrame;
#endif
out vec4 fragColor;
// The image drawn (its texels) and its size over the output's: below 1 at interactive quality,
// scaled up here by bilinear weights of the tone-mapped texels.
uniform ivec2 uDrawn;
uniform vec2 uScale;

vec3 toneMap(vec3 x) { return vec3(1.0) - exp(-x * 1.1); }

// One texel of the drawn image, each sample tone-mapped, then averaged.
vec3 resolved(ivec2 p) {
  vec3 sum = vec3(0.0);
#if SAMPLES > 1
  for (int i = 0; i < SAMPLES; ++i) sum += toneMap(texelFetch(uFrame, p, i).rgb);
  sum /= float(SAMPLES);
#else
  sum = toneMap(texelFetch(uFrame, p, 0).rgb);
#endif
  return sum;
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 sum;
  if (uScale == vec2(1.0)) {
    sum = resolved(p);
  } else {
    vec2 f = gl_FragCoord.xy * uScale - 0.5;
    ivec2 lo = ivec2(floor(f)), hi = uDrawn - 1;
    vec2 t = f - vec2(lo);
    ivec2 a = clamp(lo, ivec2(0), hi), b = clamp(lo + 1, ivec2(0), hi);
    sum = mix(mix(resolved(a), resolved(ivec2(b.x, a.y)), t.x),
              mix(resolved(ivec2(a.x, b.y)), resolved(b), t.x), t.y);
  }
  vec3 c = clamp(sum, 0.0, 1.0);
  vec3 display = mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
  float dither = (hashToUnit(pcgHash(uint(p.x) * 4099u + uint(p.y) * 7u)) - 0.5) / 255.0;
  fragColor = vec4(display + dither, 1.0);
}
