// Hair, every pass, from what the compute passes wrote this frame (hair_common.glsl).
// SHADOW_PASS: line segments seen from the light, into the deep opacity maps. CHILD_LINES:
// the children, line segments whose vertex ids are child points (their light, colour and
// coverage already computed); otherwise the guides, whose vertex ids are spline points,
// drawn as camera-facing ribbons (two vertices a point), as lines where they are thinner
// than a pixel (GUIDE_LINES), or, for the shadows, lines.
#include "render/hair_common.glsl"

// Far outside the clip volume: a child thinned away draws nothing.
const vec4 kNowhere = vec4(2.0, 2.0, 2.0, 1.0);

#ifdef SHADOW_PASS

out float vOpacity;  // what each fragment adds to the opacity layers (hair_opacity.frag)

void main() {
  uint id = uint(gl_VertexID);
#ifdef CHILD_LINES
  vec4 c = childPoints[id];
  gl_Position = c.w < 0.0 ? kNowhere : uLightViewProj * vec4(c.xyz, 1.0);
  // uChildren2.z: the children drawn into the maps stand for all of them.
  float share = max(c.w, 0.0) * uChildren2.z;
#else
  vec4 g = guidePoints[id];
  gl_Position = uLightViewProj * vec4(g.xyz, 1.0);
  float share = shadowShare(guideTangents[id].xyz, pointStrand[id], g.w);
#endif
  // uChildren.z: more opacity per strand when only a share of the strands is drawn.
  vOpacity = uTipColor.a * uChildren.z * share;
}

#else

out vec3 vColor;      // shaded, linear
out float vCoverage;  // share of the pixel's samples to cover, 0..1
flat out uint vStrand;

void main() {
  uint id = uint(gl_VertexID);
#ifdef CHILD_LINES
  vec4 c = childPoints[id];
  uvec4 look = childColors[id];
  vec2 rg = unpackHalf2x16(look.x), ba = unpackHalf2x16(look.y);
  vColor = vec3(rg, ba.x);
  vCoverage = ba.y;
  vStrand = look.z;
  gl_Position = c.w < 0.0 ? kNowhere : uViewProj * vec4(c.xyz, 1.0);
#elif defined(GUIDE_LINES)
  // Guides thinner than a pixel: lines one pixel wide covering their share of it.
  vec4 g = guidePoints[id];
  uint guide = pointStrand[id];
  vStrand = guideStrandId(guide);
  vColor = hairAlbedo(guide, vStrand, g.w) * guideShade[2u * id].rgb + guideShade[2u * id + 1u].rgb;
  gl_Position = uViewProj * vec4(g.xyz, 1.0);
  vCoverage = uTipColor.a * min(screenWidth(gl_Position, guide, g.w), 1.0);
#else
  uint point = id >> 1u;
  vec4 g = guidePoints[point];
  uint guide = pointStrand[point];
  vStrand = guideStrandId(guide);
  vColor = hairAlbedo(guide, vStrand, g.w) * guideShade[2u * point].rgb +
           guideShade[2u * point + 1u].rgb;
  vec4 c = uViewProj * vec4(g.xyz, 1.0);
  float width = screenWidth(c, guide, g.w);
  // Ribbon: offset the centre line across its screen-space direction by half the width.
  vec4 dc = uViewProj * vec4(guideTangents[point].xyz, 0.0);
  vec2 dir = (dc.xy * c.w - c.xy * dc.w) * uViewport.xy;  // d(pixels)/d(parameter), scaled
  dir = dot(dir, dir) > 1e-20 ? normalize(dir) : vec2(1.0, 0.0);
  // A ribbon narrower than about a pixel and a half misses a fixed sample position in some
  // pixels along its length and breaks into dots: draw it that wide and cover
  // proportionally fewer samples instead (width-based fading).
  const float kMinWidth = 1.5;
  vCoverage = uTipColor.a * min(width / kMinWidth, 1.0);
  width = max(width, kMinWidth);
  float side = (id & 1u) == 1u ? 1.0 : -1.0;
  c.xy += vec2(-dir.y, dir.x) * (side * width) * uViewport.zw * c.w;
  gl_Position = c;
#endif
}
#endif
