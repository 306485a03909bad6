// The head's distance field (sim/head/distance_grid.h): a vec4 per node, the gradient (xyz) and the
// distance (w), read by trilinear interpolation in the head's frame. The float twin of
// DistanceGrid::sample.
#ifdef CSM_STORAGE_READS
layout(std430, binding = CSM_BIND_HEAD_FIELD) readonly buffer HeadFieldIn { vec4 headFieldIn[]; };
#define headFieldNode(i) headFieldIn[uint(i)]
#else
layout(binding = CSM_TEX_HEAD_FIELD) uniform samplerBuffer headFieldTex;
#define headFieldNode(i) texelFetch(headFieldTex, i)
#endif

bool headIsField() {
  return P.headIsField != 0u;
}

// Gradient (xyz, not normalised) and distance (w) at p, head frame. Beyond the grid: the
// border's value plus the way to it (the border lies outside the head).
vec4 headFieldSample(vec3 p) {
  ivec3 dims = ivec3(P.headFieldDims);
  vec3 f = (p - P.headFieldOrigin) / P.headFieldCell;
  vec3 inside = clamp(f, vec3(0.0), vec3(dims - 1));
  float beyond = length(f - inside) * P.headFieldCell;
  ivec3 c = min(ivec3(floor(inside)), dims - 2);
  vec3 t = inside - vec3(c);
  int base = c.x + dims.x * (c.y + dims.y * c.z);
  int dy = dims.x, dz = dims.x * dims.y;
  vec4 v = mix(mix(mix(headFieldNode(base), headFieldNode(base + 1), t.x),
                   mix(headFieldNode(base + dy), headFieldNode(base + dy + 1),
                       t.x),
                   t.y),
               mix(mix(headFieldNode(base + dz),
                       headFieldNode(base + dz + 1), t.x),
                   mix(headFieldNode(base + dz + dy),
                       headFieldNode(base + dz + dy + 1), t.x),
                   t.y),
               t.z);
  v.w += beyond;
  return v;
}

// A world point in the frame of a head at pose `head` (a rigid transform).
vec3 toHeadFrame(mat4 head, vec3 x) {
  return transpose(mat3(head)) * (x - head[3].xyz);
}
