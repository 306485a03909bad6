// Hair, every pass. SHADOW_PASS: points seen from the light, drawn as line strips into the
// deep opacity maps. Otherwise: camera-facing ribbons of render.strand_width pixels (or
// render.strand_width_m metres), shaded per vertex with the deep-opacity transmittance.
#include "render/hair_common.glsl"

#ifdef SHADOW_PASS

out float vOpacity;  // what each fragment adds to the opacity layers (hair_opacity.frag)

void main() {
  HairVertex v = hairVertex(uCounts2.x);
  gl_Position = uLightViewProj * vec4(v.position, 1.0);
  // A line one texel wide lights one texel per step along its major axis: per unit of length
  // it lights max(|dx|, |dy|) / texel texels, where the strand covers width x length. Each
  // fragment then stands for width / (texel max(|dx|, |dy|)) of its texel, and adding the
  // strand's opacity times that share makes the opacity per square metre of the light's view
  // the hair's own, whatever the map's resolution. (An opacity per fragment alone would
  // darken the shadows by the texel's side: four times at 256 texels as at 1024.) The light
  // is orthographic, so the tangent's direction in its view is the same in clip space.
  vec2 d = (uLightViewProj * vec4(v.tangent, 0.0)).xy;
  float len = length(d);
  float major = len > 1e-12 ? max(abs(d.x), abs(d.y)) / len : 1.0;
  float share = uWidth.z * strandWidthFactor(v) / (uLightRange.w * major);
  // uFollow.z: more opacity per strand when only a share of the strands is drawn.
  vOpacity = uTipColor.a * uFollow.z * share;
}

#else
#include "render/dom.glsl"

out vec3 vColor;      // shaded, linear
out float vCoverage;  // share of the pixel's samples to cover, 0..1
flat out uint vStrand;

// sin(T, H)^exponent, faded where the highlight would come from behind the strand.
float strandSpecular(vec3 T, vec3 H, float exponent) {
  float th = dot(T, H);
  float sinTH = sqrt(max(1.0 - th * th, 0.0));
  return smoothstep(-1.0, 0.0, th) * pow(sinTH, exponent);
}

// Smooth 1D value noise along the strand, for the secondary highlight's glints.
float strandNoise(float x, uint seed) {
  float i = floor(x);
  float f = x - i;
  float a = hashToUnit(pcgHash(seed + uint(int(i) & 0xffff)));
  float b = hashToUnit(pcgHash(seed + uint(int(i + 1.0) & 0xffff)));
  return mix(a, b, f * f * (3.0 - 2.0 * f));
}

// Kajiya & Kay 1989 with two shifted highlights (Scheuermann 2004, "Hair Rendering and
// Shading", after Marschner et al. 2003): the primary (R) highlight in the light's colour,
// the secondary (TRT) tinted by the hair and broken into glints along the strand.
// Shaded per vertex: the spline points are a few pixels apart and the tangent turns slowly
// along them, while a ribbon 1-2 pixels wide costs a software rasterizer far more fragments
// (whole 2x2 quads and multisample coverage) than vertices.
vec3 shadeHair(vec3 P, vec3 tangent, vec3 albedo, float light, float s, uint h) {
  vec3 T = normalize(tangent);
  vec3 V = normalize(uEye.xyz - P);
  vec3 L = -uLightDir.xyz;
  // The ribbon faces the camera, so the strand's normal is the view direction made
  // perpendicular to the tangent; the highlights shift the tangent along it.
  vec3 N = V - dot(V, T) * T;
  N = dot(N, N) > 1e-12 ? normalize(N) : vec3(0.0, 1.0, 0.0);
  vec3 H = normalize(L + V);

  float tl = dot(T, L);
  float diffuse = sqrt(max(1.0 - tl * tl, 0.0));  // Kajiya-Kay: sin(T, L)

  float tilt = (hashToUnit(pcgHash(h)) - 0.5) * 0.04;  // per-strand cuticle tilt
  vec3 T1 = normalize(T + (uSpecShift.x + tilt) * N);
  vec3 T2 = normalize(T + (uSpecShift.y + tilt) * N);
  float spec1 = uSpecStrength.x * strandSpecular(T1, H, uSpecShift.z);
  float glint = 0.4 + 1.2 * strandNoise(s * 24.0, h);
  float spec2 = uSpecStrength.y * glint * strandSpecular(T2, H, uSpecShift.w);

  vec3 lightColor = uLightColor.rgb * uLightDir.w * light;
  // Ambient is dimmed inside the hair volume too: the deep layers see less of the sky.
  float ambient = uLightColor.a * mix(0.4, 1.0, light);
  return albedo * ambient +
         lightColor * (albedo * diffuse + spec1 + spec2 * normalize(albedo + 1e-4)) / kPi;
}

void main() {
  HairVertex v = hairVertex(uCounts.x);
  vStrand = v.strand;

  // Colour: root-to-tip gradient, per-strand brightness variation, groom colours if any.
  uint h = pcgHash(v.strand);
  vec3 root = uRootColor.rgb, tip = uTipColor.rgb;
  if ((uCounts.w & 1) != 0) {
    // A groom colour is the strand's colour; the preset's gradient keeps its darker root.
    vec3 c = strandAttributes[v.guide].rgb;
    float lr = dot(root, vec3(0.3, 0.59, 0.11)), lt = dot(tip, vec3(0.3, 0.59, 0.11));
    root = c * (lt > 0.0 ? clamp(lr / lt, 0.0, 1.0) : 1.0);
    tip = c;
  }
  float variation = 1.0 + uRootColor.a * (2.0 * hashToUnit(h) - 1.0);
  vec3 albedo = mix(root, tip, smoothstep(0.0, 1.0, v.s)) * variation;

  float light = hairTransmittance(v.position) * headVisibility(v.position);
  vColor = shadeHair(v.position, v.tangent, albedo, light, v.s, h);

  // Ribbon: offset the centre line across its screen-space direction by half the width.
  vec4 c = uViewProj * vec4(v.position, 1.0);
  vec4 dc = uViewProj * vec4(v.tangent, 0.0);
  vec2 dir = (dc.xy * c.w - c.xy * dc.w) * uViewport.xy;  // d(pixels)/d(parameter), scaled
  dir = dot(dir, dir) > 1e-20 ? normalize(dir) : vec2(1.0, 0.0);
  // In pixels, or in metres seen from the camera: pixels per metre at depth 1 over the depth
  // (clip w: the view depth in a perspective, 1 in an orthographic view).
  float width = strandWidthFactor(v) *
                (uWidth.x > 0.0 ? uWidth.x * uWidth.y / max(c.w, 1e-6) : uSpecStrength.z);
  // A ribbon narrower than about a pixel and a half misses a fixed sample position in some
  // pixels along its length and breaks into dots: draw it that wide and cover
  // proportionally fewer samples instead (width-based fading).
  const float kMinWidth = 1.5;
  vCoverage = uTipColor.a * min(width / kMinWidth, 1.0);
  width = max(width, kMinWidth);
  c.xy += vec2(-dir.y, dir.x) * (v.side * width) * uViewport.zw * c.w;
  gl_Position = c;
}
#endif
