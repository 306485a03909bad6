// Children: render.children hairs drawn around each guide, made anew every frame from the
// guide's spline points (hair_points.comp), a point every uCounts.z of them (children are
// thinner than a pixel: half the guide's subdivision draws them as smoothly). Child k of
// guide g at its point p is item childFirst(g) * children + k * childCount(g) + p, so a
// guide's children lie together and each child's points in order. A child:
//   - starts at a random point of a disc of radius uChildren.x (or the roots' spacing)
//     around its guide's root, in
//     the guide's frame, pushed into the hair on a hairline or parting, and is thinned
//     away there (the density around its guide's root, guideLinks[2g].w);
//   - closes in on its guide toward the tip by the clump uChildren.y (a clump profile);
//   - wanders by up to uChildren.w, growing from the root, with its own smooth noise;
//   - is shorter than its guide by up to uChildren2.x (its points follow a shorter part of
//     the guide's curve);
//   - one in uChildren2.y lies between its guide and the guide's neighbour, following
//     both, unless the two guides part (a parting stays a parting).
// Written: xyz the point, w the opacity share it puts into the shadow maps; w < 0 for a
// child thinned away. hair_child_shade.comp lights the points once the maps are drawn.
#include "render/hair_common.glsl"
#include "render/hair_compute.glsl"

uniform uint uItems;  // a child's points over all guides, times the children

// The guide's curve at fractional spline point `fp` of [first, first + count).
vec3 guideAt(uint first, uint count, float fp) {
  uint p0 = min(uint(fp), count - 1u);
  uint p1 = min(p0 + 1u, count - 1u);
  return mix(guidePoints[first + p0].xyz, guidePoints[first + p1].xyz, fp - float(p0));
}

void main() {
  uint j = invocationIndex();
  if (j >= uItems) return;
  ChildItem c = childItem(j);
  uint guide = c.guide, first = c.first, count = c.count;
  uint h = c.id;

  vec4 hairline = guideLinks[2u * guide];
  float density = hairline.w;
  if (hashToUnit(pcgHash(h ^ 0x68bc21ebu)) >= smoothstep(0.35, 0.85, density)) {
    childPoints[j] = vec4(0.0, 0.0, 0.0, -1.0);
    return;
  }

  float fp = childGuidePoint(c);
  uint p0 = min(uint(fp), count - 1u);
  uint p1 = min(p0 + 1u, count - 1u);
  float f = fp - float(p0);
  vec3 base = mix(guidePoints[first + p0].xyz, guidePoints[first + p1].xyz, f);
  float s = mix(guidePoints[first + p0].w, guidePoints[first + p1].w, f);
  vec3 T = mix(guideTangents[first + p0].xyz, guideTangents[first + p1].xyz, f);
  vec3 unitT = dot(T, T) > 1e-24 ? normalize(T) : vec3(0.0, -1.0, 0.0);
  vec3 N = mix(guideFrames[first + p0].xyz, guideFrames[first + p1].xyz, f);
  N -= dot(N, unitT) * unitT;
  N = dot(N, N) > 1e-12 ? normalize(N) : guideFrames[first + p0].xyz;
  vec3 B = cross(unitT, N);

  vec4 link = guideLinks[2u * guide + 1u];
  float radius = uChildren.x > 0.0 ? uChildren.x : link.z;
  uint neighbour = floatBitsToUint(link.x);
  if (neighbour != guide && hashToUnit(pcgHash(h + 4u)) < uChildren2.y) {
    uint nFirst = splineFirst[neighbour];
    uint nCount = splineFirst[neighbour + 1u] - nFirst;
    vec3 other = guideAt(nFirst, nCount, s * float(nCount - 1u));
    float apart = length(other - base);
    float together = 1.0 - smoothstep(1.5 * link.y + radius, 3.0 * link.y + 2.0 * radius, apart);
    base = mix(base, other, 0.5 * hashToUnit(pcgHash(h + 5u)) * together);
  }

  // The disc at the root, its centre moved into the hair where the density falls.
  float r = radius * sqrt(hashToUnit(pcgHash(h + 2u)));
  float phi = 2.0 * CSM_PI * hashToUnit(pcgHash(h + 3u));
  vec2 offset = r * vec2(cos(phi), sin(phi));
  offset += hairline.xy * radius * clamp(2.0 * (1.0 - density), 0.0, 1.0);
  offset *= 1.0 - uChildren.y * s;
  vec2 wander = vec2(valueNoise(4.0 * s, h + 6u), valueNoise(4.0 * s, h + 7u));
  offset += uChildren.w * s * (2.0 * wander - 1.0);
  childPoints[j] = vec4(base + offset.x * N + offset.y * B, shadowShare(T, guide, s));
}
