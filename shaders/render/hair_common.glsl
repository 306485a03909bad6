// Hair geometry by vertex pulling: every vertex of every pass is computed from the
// simulation's positions SSBO and gl_VertexID, with no vertex buffer and no CPU copy.
//
// The index buffers (built once per groom) encode a vertex as
//   guide << (pointBits + 1) | point << 1 | side
// where `point` counts the spline points of the strand (subdivision per simulated segment)
// and `side` is the ribbon edge. Follow hairs are instances of their guide: gl_InstanceID 0
// is the guide itself, 1..followCount the render-only strands around it.
#ifndef HAIR_COMMON_GLSL
#define HAIR_COMMON_GLSL
#include "render/frame.glsl"

layout(std430, binding = POSITIONS_BINDING) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = REST_POSITIONS_BINDING) readonly buffer RestPositions {
  vec4 restPositions[];
};
layout(std430, binding = STRAND_FIRST_BINDING) readonly buffer StrandFirst { uint strandFirst[]; };
layout(std430, binding = STRAND_ATTRIBUTES_BINDING) readonly buffer StrandAttributes {
  vec4 strandAttributes[];  // rgb: groom colour; a: thickness relative to the groom's mean
};

struct HairVertex {
  vec3 position;  // world
  vec3 tangent;   // world, d position / d parameter (not unit)
  float s;        // 0 at the root, 1 at the tip
  uint guide;     // simulated strand
  uint strand;    // drawn strand: guide * (followCount + 1) + follow
  float side;     // -1 or +1: which edge of the ribbon
};

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

// Where follow hair `follow` of guide `guide` sits relative to its guide. At rest it is a
// random point of the disc of radius follow_spread in the plane normal to the guide's root
// tangent (fixed by a hash: the same every frame and run), turned with the head, and widening
// toward the tip by uFollow.y as real clumps do. As the guide bends, the offset turns by the
// shortest rotation from the guide's rest tangent to its current one at the same point, so a
// follow hair keeps its place beside the guide's curve instead of sliding along it.
vec3 followOffset(uint guide, uint follow, uint first, uint n, uint seg, float u, vec3 tangent,
                  float s) {
  vec3 restRoot = normalize(restPositions[first + 1u].xyz - restPositions[first].xyz);
  vec3 b1, b2;
  basisAround(restRoot, b1, b2);
  uint h = pcgHash(guide * 977u + follow * 7919u + 17u);
  float r = uFollow.x * sqrt(hashToUnit(h));
  float phi = 2.0 * kPi * hashToUnit(pcgHash(h));
  mat3 headRotation = mat3(uHeadRotation);
  vec3 d = headRotation * (r * (cos(phi) * b1 + sin(phi) * b2));
  d *= 1.0 + uFollow.y * s;

  vec3 restP, restT;
  strandSpline(true, first, n, seg, u, restP, restT);
  vec3 a = normalize(headRotation * restT);
  vec3 b = normalize(tangent);
  float c = dot(a, b);
  // Rodrigues' formula for the rotation taking a to b. It is undefined where the strand has
  // turned right round (c -> -1); there the rigid offset is blended in instead.
  if (c > -0.9) {
    vec3 v = cross(a, b);
    vec3 rotated = d * c + cross(v, d) + v * (dot(v, d) / (1.0 + c));
    d = mix(d, rotated, smoothstep(-0.9, -0.5, c));
  }
  return d;
}

// A strand's width relative to the nominal one: the groom's thickness where it has one, and
// thinner toward the tip, as a hair is. Every pass uses it: the ribbons' width on screen and
// the opacity a strand puts into the shadow maps.
float strandWidthFactor(HairVertex v) {
  float thickness = (uCounts.w & 2) != 0 ? strandAttributes[v.guide].a : 1.0;
  return thickness * mix(1.0, 0.5, smoothstep(0.7, 1.0, v.s));
}

// Decodes the vertex and evaluates its strand. `subdivision` is the pass's spline segments
// per simulated segment.
HairVertex hairVertex(int subdivision) {
  HairVertex v;
  uint id = uint(gl_VertexID);
  uint pointBits = uint(uCounts.z);
  v.side = (id & 1u) == 1u ? 1.0 : -1.0;
  uint point = (id >> 1u) & ((1u << pointBits) - 1u);
  v.guide = id >> (pointBits + 1u);
  uint follow = uint(gl_InstanceID);
  v.strand = v.guide * uint(uCounts.y + 1) + follow;

  uint first = strandFirst[v.guide];
  uint n = strandFirst[v.guide + 1u] - first;
  uint sub = uint(subdivision);
  uint seg = min(point / sub, n - 2u);
  float u = float(point - seg * sub) / float(sub);
  strandSpline(false, first, n, seg, u, v.position, v.tangent);
  v.s = (float(seg) + u) / float(n - 1u);
  if (follow > 0u)
    v.position += followOffset(v.guide, follow, first, n, seg, u, v.tangent, v.s);
  return v;
}
#endif  // HAIR_COMMON_GLSL
