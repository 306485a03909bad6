// The head's distance field (sim/head_shape.h): a vec4 per node, the gradient (xyz) and the
// distance (w), read by trilinear interpolation in the head's frame. The float twin of
// DistanceGrid::sample and of pushOutOfHeadField in sim/cpu/cpu_solver.cpp.
layout(binding = CSM_TEX_HEAD_FIELD) uniform samplerBuffer headFieldTex;

bool headIsField() {
  return P.headFieldDims.w != 0u;
}

// Gradient (xyz, not normalised) and distance (w) at p, head frame. Beyond the grid: the
// border's value plus the way to it (the border lies outside the head).
vec4 headFieldSample(vec3 p) {
  ivec3 dims = ivec3(P.headFieldDims.xyz);
  vec3 f = (p - P.headField.xyz) / P.headField.w;
  vec3 inside = clamp(f, vec3(0.0), vec3(dims - 1));
  float beyond = length(f - inside) * P.headField.w;
  ivec3 c = min(ivec3(floor(inside)), dims - 2);
  vec3 t = inside - vec3(c);
  int base = c.x + dims.x * (c.y + dims.y * c.z);
  int dy = dims.x, dz = dims.x * dims.y;
  vec4 v = mix(mix(mix(texelFetch(headFieldTex, base), texelFetch(headFieldTex, base + 1), t.x),
                   mix(texelFetch(headFieldTex, base + dy), texelFetch(headFieldTex, base + dy + 1),
                       t.x),
                   t.y),
               mix(mix(texelFetch(headFieldTex, base + dz),
                       texelFetch(headFieldTex, base + dz + 1), t.x),
                   mix(texelFetch(headFieldTex, base + dz + dy),
                       texelFetch(headFieldTex, base + dz + dy + 1), t.x),
                   t.y),
               t.z);
  v.w += beyond;
  return v;
}

// A world point in the frame of a head at pose `head` (a rigid transform).
vec3 toHeadFrame(mat4 head, vec3 x) {
  return transpose(mat3(head)) * (x - head[3].xyz);
}

// Moves p (world) out of the field's surface inflated by radius, along the field's normal (a
// second step takes what the first left: the field is close to a distance, not exactly one).
// With a strain limit, keeps p within maxLength of prev: when the push is out of reach, the
// nearest point of the circle where the tangent plane there meets the ball of reach.
// `clearance` gets the field's distance at the point it leaves p at, where it read it (p
// untouched, or the projection), else kUnknownClearance (the circle's point).
const float kUnknownClearance = -1e30;
bool pushOutOfHeadField(inout vec3 p, vec3 prev, mat4 head, float radius, float maxLength,
                        out vec3 normal, out float clearance) {
  normal = vec3(0.0, 1.0, 0.0);
  vec3 local = toHeadFrame(head, p);
  vec4 s = headFieldSample(local);
  clearance = s.w;
  if (s.w >= radius) return false;
  vec3 n = vec3(0.0, 1.0, 0.0);
  for (int step = 0; step < 2 && s.w < radius; ++step) {
    float len = length(s.xyz);
    n = len > 1e-12 ? s.xyz / len : vec3(0.0, 1.0, 0.0);
    local += (radius - s.w) * n;
    s = headFieldSample(local);
  }
  vec3 target = mat3(head) * local + head[3].xyz;
  normal = mat3(head) * n;
  p = target;
  clearance = s.w;
  if (maxLength <= 0.0 || length(target - prev) <= maxLength) return true;
  float above = dot(prev - target, normal);
  if (abs(above) >= maxLength) return true;  // no circle: keep the projection
  vec3 centre = prev - above * normal;
  vec3 side = target - centre;
  float sideLen = length(side);
  if (sideLen < 1e-15) return true;
  p = centre + side * (sqrt(maxLength * maxLength - above * above) / sideLen);
  clearance = kUnknownClearance;
  return true;
}
