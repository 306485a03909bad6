// Deep opacity layers (Yuksel & Keyser 2008): with additive blending into an RGBA target,
// each hair fragment adds its opacity to the layer its depth falls in and to every layer
// behind it, so layer k ends up holding the opacity nearer than z0 + (k+1) spacing.
#include "render/frame.glsl"

layout(binding = CSM_RENDER_LIGHT_DEPTH_UNIT) uniform sampler2D uLightDepth;
in float vOpacity;  // the strand's opacity times the share of the texel it covers (hair.vert)
out vec4 fragLayers;

void main() {
  float z0 = texelFetch(uLightDepth, ivec2(gl_FragCoord.xy), 0).r;
  float t = (gl_FragCoord.z - z0) * (uLightRange.x / uSpecStrength.w);
  fragLayers = vOpacity * vec4(step(t, 1.0), step(t, 2.0), step(t, 3.0), 1.0);
}
