// Smooth-shaded head that receives the hair's shadow (the deep opacity maps) and its own.
#include "render/dom.glsl"

in vec3 vPosition;
in vec3 vNormal;
out vec4 fragColor;

void main() {
  vec3 N = normalize(vNormal);
  vec3 L = -uLightDir.xyz;
  vec3 V = normalize(uEye.xyz - vPosition);
  // Lambert wrapped a little, as skin scatters light past the terminator.
  float wrap = 0.2;
  float diffuse = max((dot(N, L) + wrap) / (1.0 + wrap), 0.0);
  float visibility = hairTransmittance(vPosition) * headVisibility(vPosition);
  vec3 H = normalize(L + V);
  float spec = 0.04 * pow(max(dot(N, H), 0.0), 40.0);
  // Hemispherical ambient: more from above than from the ground.
  float sky = 0.75 + 0.25 * N.y;
  vec3 albedo = uHeadColor.rgb;
  vec3 light = uLightColor.rgb * uLightDir.w * visibility;
  vec3 color = albedo * uLightColor.a * sky + light * (albedo * diffuse / kPi + spec);
  fragColor = vec4(color, 1.0);
}
