// Every guide's spline points for this frame: position and s, tangent, and a frame normal.
// The frame is the root's basis (around the rest root tangent, turned with the head) turned
// at each point by the shortest rotation from the rest tangent there to the current one: it
// follows the strand as it bends, so children placed in it keep their place beside the
// guide's curve instead of sliding along it.
#include "render/hair_common.glsl"
#include "render/hair_compute.glsl"

void main() {
  uint i = invocationIndex();
  if (i >= uint(uCounts2.x)) return;
  uint guide = pointStrand[i];
  uint first = strandFirst[guide];
  uint n = strandFirst[guide + 1u] - first;
  uint point = i - splineFirst[guide];
  uint sub = uint(uCounts.x);
  uint seg = min(point / sub, n - 2u);
  float u = float(point - seg * sub) / float(sub);
  vec3 p, dp;
  strandSpline(false, first, n, seg, u, p, dp);
  float s = (float(seg) + u) / float(n - 1u);

  // The root's rest direction (a root segment of zero length, which the solver allows, takes
  // straight down: a frame of NaN would give every child of the guide NaN points).
  vec3 root = restPositions[first + 1u].xyz - restPositions[first].xyz;
  vec3 b1, b2;
  basisAround(dot(root, root) > 1e-24 ? normalize(root) : vec3(0.0, -1.0, 0.0), b1, b2);
  mat3 headRotation = mat3(uHeadRotation);
  vec3 normal = headRotation * b1;
  vec3 restP, restT;
  strandSpline(true, first, n, seg, u, restP, restT);
  vec3 a = normalize(headRotation * restT);
  vec3 b = dot(dp, dp) > 1e-24 ? normalize(dp) : a;
  float c = dot(a, b);
  // Rodrigues' formula for the rotation taking a to b. It is undefined where the strand has
  // turned right round (c -> -1); there the unturned frame is blended in instead.
  if (c > -0.9) {
    vec3 v = cross(a, b);
    vec3 turned = normal * c + cross(v, normal) + v * (dot(v, normal) / (1.0 + c));
    normal = mix(normal, turned, smoothstep(-0.9, -0.5, c));
  }
  normal -= dot(normal, b) * b;
  // Where the strand runs along the frame's normal, any perpendicular will do.
  vec3 other = abs(b.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 0.0, 1.0);
  normal = dot(normal, normal) > 1e-12 ? normalize(normal) : normalize(cross(b, other));

  guidePoints[i] = vec4(p, s);
  guideTangents[i] = vec4(dp, 0.0);
  guideFrames[i] = vec4(normal, 0.0);
}
