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

// The mannequin's painted face (uFaceEye.w set; p in the head frame from the placement centre,
// the head's part only): the eyeballs' white, the iris with its darker rim and the pupil, the
// lips' red. Returns the albedo; `eye` is how much of the point lies on an eyeball (its cornea
// glossy).
vec3 paintedFace(vec3 p, vec3 skin, out float eye) {
  eye = 0.0;
  if (uFaceEye.w < 0.5 || vSphere != 0) return skin;
  vec3 m = vec3(abs(p.x), p.y, p.z);  // the right side; the left mirrors it
  vec3 q = m - uFaceEye.xyz;
  // On the ball or its cornea (the sculpted eye's own two spheres) rather than the lids.
  float ball = length(q) - uFaceEyeSizes.x;
  float cornea = length(q - vec3(0.0, 0.0, uFaceEyeSizes.y)) - uFaceEyeSizes.z;
  eye = 1.0 - smoothstep(0.00025, 0.0007, min(abs(ball), abs(cornea)));
  float across = length(q.xy) * step(0.0, q.z);  // from the gaze's axis, on the front only
  float pixel = fwidth(across) + 1e-6;
  float iris = 1.0 - smoothstep(uFaceEyeSizes.w - pixel, uFaceEyeSizes.w + pixel, across);
  if (q.z <= 0.0) iris = 0.0;
  float pupil = 1.0 - smoothstep(uFaceMouth.w - pixel, uFaceMouth.w + pixel, across);
  vec3 sclera = vec3(0.80, 0.76, 0.72);
  // The iris darker at its rim (the limbal ring) and lighter about the pupil.
  float r = across / uFaceEyeSizes.w;
  vec3 irisColour = uIrisColor.rgb * mix(1.25, 0.45, smoothstep(0.55, 1.0, r));
  vec3 eyeColour = mix(mix(sclera, irisColour, iris), vec3(0.012), pupil * iris);
  vec3 albedo = mix(skin, eyeColour, eye);
  // The lips' red, on the front of the mouth, fading at the vermilion's border.
  vec3 l = (m - uFaceMouth.xyz) / vec3(uFaceLips.x, uFaceLips.y, 1.0);
  float lips = (1.0 - smoothstep(0.75, 1.0, length(l.xy))) * smoothstep(-0.012, -0.006, l.z);
  albedo = mix(albedo, skin * vec3(0.94, 0.70, 0.68), lips * (1.0 - eye));
  return albedo;
}

void main() {
  vec3 N = normalize(vNormal);
  vec3 L = -uLightDir.xyz;
  vec3 V = normalize(uEye.xyz - vPosition);
  // Lambert wrapped a little, as skin scatters light past the terminator.
  float wrap = 0.2;
  float diffuse = max((dot(N, L) + wrap) / (1.0 + wrap), 0.0);
  // The head's own shadow looked up a texel and a half off the surface along its normal, so that a
  // fold thinner than the map's texels (a lid's margin, the lips' line) does not shadow itself
  // in specks.
  float visibility = hairTransmittanceSoft(vPosition) *
                     headVisibilitySoft(vPosition + N * (1.5 * uLightRange.w));
  vec3 H = normalize(L + V);
  float spec = 0.04 * pow(max(dot(N, H), 0.0), 40.0);
  // Hemispherical ambient: more from above than from the ground.
  float sky = 0.75 + 0.25 * N.y;
  // Where hair grows (in the head's own frame), the scalp takes the roots' colour: gaps
  // between strands then read as dense hair rather than bare skin.
  vec4 scalp = texture(uScalp, vec3(octahedral(normalize(vScalpDir)), float(vSphere)));
  vec3 rootColour = (uCounts.w & 1) != 0 ? scalp.rgb : uRootColor.rgb;
  float eye;
  vec3 skin = paintedFace(vScalpDir, uHeadColor.rgb, eye);
  vec3 albedo = mix(skin, rootColour * 0.7, scalp.a);
  spec *= 1.0 - scalp.a;
  // The cornea is wet: a small sharp highlight (the eye's catchlight).
  spec = mix(spec, 0.9 * pow(max(dot(N, H), 0.0), 400.0), eye);
  vec3 light = uLightColor.rgb * uLightDir.w * visibility;
  vec3 color = albedo * uLightColor.a * sky + light * (albedo * diffuse / CSM_PI + spec);
  fragColor = vec4(color, 1.0);
}
