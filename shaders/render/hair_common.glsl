// The drawn hair, shared by the render's compute passes and its vertex shaders.
//
// Once a frame, hair_points.comp evaluates every guide (simulated strand) as a Catmull-Rom
// spline at render.subdivision points per simulated segment: position, tangent and a frame
// that turns with the strand. hair_children.comp places each guide's render.children
// children around those points (and the opacity each puts into the shadow maps). Once the
// deep opacity maps are drawn, hair_shade.comp lights each guide point and
// hair_child_shade.comp gives each child point its guide point's light, its own colour and
// its coverage. The vertex shaders then only read: a guide's vertex id is a spline point's
// index (times two plus the side for a ribbon), a child's its child point's, and a child's
// vertex reads two vectors.
#ifndef HAIR_COMMON_GLSL
#define HAIR_COMMON_GLSL
#include "render/frame.glsl"

layout(std430, binding = CSM_RENDER_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = CSM_RENDER_REST_POSITIONS) readonly buffer RestPositions {
  vec4 restPositions[];
};
layout(std430, binding = CSM_RENDER_STRAND_FIRST) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = CSM_RENDER_STRAND_ATTRIBUTES) readonly buffer StrandAttributes {
  vec4 strandAttributes[];  // rgb: groom colour; a: thickness relative to the groom's mean
};
layout(std430, binding = CSM_RENDER_SPLINE_FIRST) readonly buffer SplineFirst { uint splineFirst[]; };
layout(std430, binding = CSM_RENDER_POINT_STRAND) readonly buffer PointStrand { uint pointStrand[]; };
// Per strand: [2s] xy: the way into the hair from the root in the frame's (normal, binormal),
// z: 0, w: the hair's density around the root relative to the middle of the scalp (1 inside,
// about 0.5 on a hairline or parting); [2s + 1] x: the neighbour strand (uint bits), y: the
// roots' distance (m), z: the typical distance between neighbouring roots (m).
layout(std430, binding = CSM_RENDER_GUIDE_LINKS) readonly buffer GuideLinks { vec4 guideLinks[]; };
layout(std430, binding = CSM_RENDER_GUIDE_POINTS) buffer GuidePoints { vec4 guidePoints[]; };
layout(std430, binding = CSM_RENDER_GUIDE_TANGENTS) buffer GuideTangents { vec4 guideTangents[]; };
layout(std430, binding = CSM_RENDER_GUIDE_FRAMES) buffer GuideFrames { vec4 guideFrames[]; };
layout(std430, binding = CSM_RENDER_GUIDE_SHADE) buffer GuideShade { vec4 guideShade[]; };
// Per child point: xyz the point, w the opacity share it puts into the shadow maps (< 0: a
// child thinned away); and its colour (half floats r g, b and coverage), drawn strand id.
layout(std430, binding = CSM_RENDER_CHILD_POINTS) buffer ChildPoints { vec4 childPoints[]; };
layout(std430, binding = CSM_RENDER_CHILD_COLORS) buffer ChildColors { uvec4 childColors[]; };
// A child has a point every uCounts.z guide spline points: childFirst[s] is the first of
// strand s's in one child's run, childStrand[q] the strand of run point q.
layout(std430, binding = CSM_RENDER_CHILD_FIRST) readonly buffer ChildFirst { uint childFirst[]; };
layout(std430, binding = CSM_RENDER_CHILD_STRAND) readonly buffer ChildStrand { uint childStrand[]; };

// Uniform Catmull-Rom through p0..p3, evaluated between p1 and p2. Uniform rather than
// centripetal because strain limiting keeps neighbouring segments within a few percent of
// the same length, where the two agree and uniform needs no square roots.
void catmullRom(vec3 p0, vec3 p1, vec3 p2, vec3 p3, float u, out vec3 p, out vec3 dp) {
  vec3 a = 2.0 * p1;
  vec3 b = p2 - p0;
  vec3 c = 2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3;
  vec3 d = -p0 + 3.0 * p1 - 3.0 * p2 + p3;
  p = 0.5 * (a + u * (b + u * (c + u * d)));
  dp = 0.5 * (b + u * (2.0 * c + 3.0 * u * d));
}

// The spline through particles [first, first + n) at segment `seg`, fraction `u`. The ends
// reflect their neighbour, so the curve starts at the root and ends at the tip.
void strandSpline(bool rest, uint first, uint n, uint seg, float u, out vec3 p, out vec3 dp) {
  uint i1 = first + seg, i2 = i1 + 1u;
  vec3 p1 = rest ? restPositions[i1].xyz : positions[i1].xyz;
  vec3 p2 = rest ? restPositions[i2].xyz : positions[i2].xyz;
  vec3 p0 = seg > 0u ? (rest ? restPositions[i1 - 1u].xyz : positions[i1 - 1u].xyz)
                     : 2.0 * p1 - p2;
  vec3 p3 = seg + 2u < n ? (rest ? restPositions[i2 + 1u].xyz : positions[i2 + 1u].xyz)
                         : 2.0 * p2 - p1;
  catmullRom(p0, p1, p2, p3, u, p, dp);
}

// An orthonormal basis around a unit vector (Duff et al. 2017, "Building an Orthonormal
// Basis, Revisited"): continuous except across n.z = 0's sign flip, and branch-free.
void basisAround(vec3 n, out vec3 b1, out vec3 b2) {
  float sgn = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (sgn + n.z);
  float b = n.x * n.y * a;
  b1 = vec3(1.0 + sgn * n.x * n.x * a, sgn * b, -sgn * n.x);
  b2 = vec3(b, sgn + n.y * n.y * a, -n.y);
}

// Smooth 1D value noise in [0, 1] at x, its lattice hashed from `seed`: glints along a
// strand, a child's wander.
float valueNoise(float x, uint seed) {
  float i = floor(x);
  float f = x - i;
  float a = hashToUnit(pcgHash(seed + uint(int(i) & 0xffff)));
  float b = hashToUnit(pcgHash(seed + uint(int(i + 1.0) & 0xffff)));
  return mix(a, b, f * f * (3.0 - 2.0 * f));
}

// Drawn strand ids, for per-strand variation and stochastic transparency: the guide's own
// index, and a hash of guide and child for a child (the same whatever render.children is).
uint guideStrandId(uint guide) { return guide; }
uint childStrandId(uint guide, uint child) {
  return pcgHash(guide * 977u + child * 7919u + 17u) | 0x80000000u;
}

// A strand's width relative to the nominal one: the groom's thickness where it has one,
// thinner toward the tip, as a hair is, and thinner on a hairline or a parting (the density
// there). Every pass uses it: the width on screen and the opacity put into the shadow maps.
float strandWidthFactor(uint guide, float s) {
  float thickness = (uCounts.w & 2) != 0 ? strandAttributes[guide].a : 1.0;
  float edge = mix(0.5, 1.0, smoothstep(0.45, 0.9, guideLinks[2u * guide].w));
  return thickness * edge * mix(1.0, 0.5, smoothstep(0.7, 1.0, s));
}

// The strand's colour before light: root-to-tip gradient, per-strand brightness variation,
// the groom's colour if it has one.
vec3 hairAlbedo(uint guide, uint strandId, float s) {
  vec3 root = uRootColor.rgb, tip = uTipColor.rgb;
  if ((uCounts.w & 1) != 0) {
    // A groom colour is the strand's colour; the preset's gradient keeps its darker root.
    vec3 c = strandAttributes[guide].rgb;
    float lr = dot(root, vec3(0.3, 0.59, 0.11)), lt = dot(tip, vec3(0.3, 0.59, 0.11));
    root = c * (lt > 0.0 ? clamp(lr / lt, 0.0, 1.0) : 1.0);
    tip = c;
  }
  float variation = 1.0 + uRootColor.a * (2.0 * hashToUnit(pcgHash(strandId)) - 1.0);
  return mix(root, tip, smoothstep(0.0, 1.0, s)) * variation;
}

// Child item j (hair_children.comp's layout): child k of guide g at its child point p is
// item childFirst(g) * children + k * childCount(g) + p.
struct ChildItem {
  uint guide, child, point;  // point: the child's, from its root
  uint first, count;         // the guide's spline points
  uint id;                   // drawn strand id
};
ChildItem childItem(uint j) {
  ChildItem c;
  uint children = uint(uCounts.y);
  c.guide = childStrand[j / children];
  uint cFirst = childFirst[c.guide];
  uint cCount = childFirst[c.guide + 1u] - cFirst;
  uint local = j - cFirst * children;
  c.child = local / cCount;
  c.point = local - c.child * cCount;
  c.first = splineFirst[c.guide];
  c.count = splineFirst[c.guide + 1u] - c.first;
  c.id = childStrandId(c.guide, c.child);
  return c;
}
// The guide's spline point (fractional, from its first) that a child's point sits beside:
// every uCounts.z-th, and a child is up to uChildren2.x shorter than its guide.
float childGuidePoint(ChildItem c) {
  return float(c.point * uint(uCounts.z)) *
         (1.0 - uChildren2.x * hashToUnit(pcgHash(c.id + 1u)));
}
// The opacity share a strand puts into the shadow maps per fragment, at a point where its
// tangent is `tangent` (see hair.vert's SHADOW_PASS).
float shadowShare(vec3 tangent, uint guide, float s) {
  // A line one texel wide lights one texel per step along its major axis: per unit of length
  // it lights max(|dx|, |dy|) / texel texels, where the strand covers width x length. Each
  // fragment then stands for width / (texel max(|dx|, |dy|)) of its texel, and adding the
  // strand's opacity times that share makes the opacity per square metre of the light's view
  // the hair's own, whatever the map's resolution. (An opacity per fragment alone would
  // darken the shadows by the texel's side: four times at 256 texels as at 1024.) The light
  // is orthographic, so the tangent's direction in its view is the same in clip space.
  vec2 d = (uLightViewProj * vec4(tangent, 0.0)).xy;
  float len = length(d);
  float major = len > 1e-12 ? max(abs(d.x), abs(d.y)) / len : 1.0;
  return uWidth.z * strandWidthFactor(guide, s) / (uLightRange.w * major);
}
// A strand's width on screen (pixels) at clip-space point `c`: render.strand_width pixels,
// or render.strand_width_m metres seen from the camera (pixels per metre at depth 1 over
// the depth, clip w: the view depth in a perspective, 1 in an orthographic view).
float screenWidth(vec4 c, uint guide, float s) {
  return strandWidthFactor(guide, s) *
         (uWidth.x > 0.0 ? uWidth.x * uWidth.y / max(c.w, 1e-6) : uSpecStrength.z);
}
#endif  // HAIR_COMMON_GLSL
