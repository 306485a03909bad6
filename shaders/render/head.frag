// Smooth-shaded head that receives the hair's shadow (the deep opacity maps) and its own.
#include "render/dom.glsl"

layout(binding = CSM_RENDER_SCALP_UNIT) uniform sampler2DArray uScalp;

in vec3 vPosition;
in vec3 vNormal;
in vec3 vScalpDir;
flat in int vSphere;
out vec4 fragColor;

// Mirrors octahedral() in render/hair_renderer.cpp (Cigolle et al. 2014).
vec2 octahedral(vec3 d) {
  d /= abs(d.x) + abs(d.y) + abs(d.z);
  vec2 p = d.xy;
  if (d.z < 0.0) p = (1.0 - abs(d.yx)) * vec2(d.x >= 0.0 ? 1.0 : -1.0, d.y >= 0.0 ? 1.0 : -1.0);
  return p * 0.5 + 0.5;
}

void main() {
  vec3 N = normalize(vNormal);
  vec3 L = -uLightDir.xyz;
  vec3 V = normalize(uEye.xyz - vPosition);
  // Lambert wrapped a little, as skin scatters light past the terminator.
  float wrap = 0.2;
  float diffuse = max((dot(N, L) + wrap) / (1.0 + wrap), 0.0);
  float visibility = hairTransmittanceSoft(vPosition) * headVisibilitySoft(vPosition);
  vec3 H = normalize(L + V);
  float spec = 0.04 * pow(max(dot(N, H), 0.0), 40.0);
  // Hemispherical ambient: more from above than from the ground.
  float sky = 0.75 + 0.25 * N.y;
  // Where hair grows (in the head's own frame), the scalp takes the roots' colour: gaps
  // between strands then read as dense hair rather than bare skin.
  vec4 scalp = texture(uScalp, vec3(octahedral(normalize(vScalpDir)), float(vSphere)));
  vec3 rootColour = (uCounts.w & 1) != 0 ? scalp.rgb : uRootColor.rgb;
  vec3 albedo = mix(uHeadColor.rgb, rootColour * 0.7, scalp.a);
  spec *= 1.0 - scalp.a;
  vec3 light = uLightColor.rgb * uLightDir.w * visibility;
  vec3 color = albedo * uLightColor.a * sky + light * (albedo * diffuse / CSM_PI + spec);
  fragColor = vec4(color, 1.0);
}
