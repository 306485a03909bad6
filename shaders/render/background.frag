// A soft studio backdrop: render.background, lighter above and darker below, with a gentle
// vignette, so both dark and blond hair stand out against it.
#include "render/frame.glsl"

in vec2 vUv;
out vec4 fragColor;

void main() {
  vec3 base = uBackground.rgb;
  vec3 color = base * mix(0.55, 1.15, smoothstep(0.0, 1.0, vUv.y));
  vec2 c = (vUv - vec2(0.5, 0.55)) * vec2(uViewport.x * uViewport.w, 1.0);
  color *= mix(1.0, 0.7, smoothstep(0.2, 0.9, length(c)));
  fragColor = vec4(color, 1.0);
}
