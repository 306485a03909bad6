// Light at every guide spline point, once the deep opacity maps of this frame are drawn:
// Kajiya & Kay 1989 with two shifted highlights (Scheuermann 2004, "Hair Rendering and
// Shading", after Marschner et al. 2003), the primary (R) highlight in the light's colour,
// the secondary (TRT) tinted by the hair and broken into glints along the strand. Written
// as two factors, so the guide and each of its children (whose colours differ) take it:
//   colour = albedo * guideShade[2i].rgb + guideShade[2i + 1].rgb.
// Children take their guide's light: they lie a few millimetres from it, within one deep
// opacity layer, and turn as it does.
#include "render/hair_common.glsl"
#include "render/hair_compute.glsl"
#include "render/dom.glsl"

// sin(T, H)^exponent, faded where the highlight would come from behind the strand.
float strandSpecular(vec3 T, vec3 H, float exponent) {
  float th = dot(T, H);
  float sinTH = sqrt(max(1.0 - th * th, 0.0));
  return smoothstep(-1.0, 0.0, th) * pow(sinTH, exponent);
}

void main() {
  uint i = invocationIndex();
  if (i >= uint(uCounts2.x)) return;
  uint guide = pointStrand[i];
  vec4 ps = guidePoints[i];
  vec3 P = ps.xyz;
  float s = ps.w;
  uint h = pcgHash(guideStrandId(guide));
  vec3 T = guideTangents[i].xyz;
  T = dot(T, T) > 1e-24 ? normalize(T) : vec3(0.0, -1.0, 0.0);
  vec3 V = normalize(uEye.xyz - P);
  vec3 L = -uLightDir.xyz;
  // The ribbon faces the camera, so the strand's normal is the view direction made
  // perpendicular to the tangent; the highlights shift the tangent along it.
  vec3 N = V - dot(V, T) * T;
  N = dot(N, N) > 1e-12 ? normalize(N) : vec3(0.0, 1.0, 0.0);
  vec3 H = normalize(L + V);

  float tl = dot(T, L);
  float diffuse = sqrt(max(1.0 - tl * tl, 0.0));  // Kajiya-Kay: sin(T, L)

  float tilt = (hashToUnit(h) - 0.5) * 0.04;  // per-strand cuticle tilt
  vec3 T1 = normalize(T + (uSpecShift.x + tilt) * N);
  vec3 T2 = normalize(T + (uSpecShift.y + tilt) * N);
  float spec1 = uSpecStrength.x * strandSpecular(T1, H, uSpecShift.z);
  float glint = 0.4 + 1.2 * valueNoise(s * 24.0, h);
  float spec2 = uSpecStrength.y * glint * strandSpecular(T2, H, uSpecShift.w);

  float light = hairTransmittance(P) * headVisibility(P);
  vec3 lightColor = uLightColor.rgb * uLightDir.w * light;
  // Ambient is dimmed inside the hair volume too: the deep layers see less of the sky.
  float ambient = uLightColor.a * mix(0.4, 1.0, light);
  vec3 albedo = hairAlbedo(guide, guideStrandId(guide), s);
  guideShade[2u * i] = vec4(ambient + lightColor * diffuse / CSM_PI, 0.0);
  guideShade[2u * i + 1u] =
      vec4(lightColor * (spec1 + spec2 * normalize(albedo + 1e-4)) / CSM_PI, 0.0);
}
