// A sample of the head's distance field (sim/head/distance_grid.h): a vec4 per node, the gradient
// (xyz) and the distance (w), read by trilinear interpolation in the head's frame. The one sample
// in GLSL, for the solver's passes (head_field.glsl) and the follower pass
// (shaders/render/hair_followers.comp); the float twin of DistanceGrid::sample, which
// tests/gpu/twins_test.cpp checks it against. The includer defines headFieldNode(i), the node i
// as it reads it.
#ifndef CSM_SIM_HEAD_FIELD_SAMPLE_GLSL
#define CSM_SIM_HEAD_FIELD_SAMPLE_GLSL

// Gradient (xyz, not normalised) and distance (w) at p (the part's frame) of the field of `dims`
// nodes from `origin`, `cell` apart, its first node `offset` (the torso's follows the head's in
// one buffer). Beyond the grid: the border's value plus the way to it (the border lies outside
// the part).
vec4 headFieldAt(ivec3 dims, vec3 origin, float cell, vec3 p, int offset) {
  vec3 f = (p - origin) / cell;
  vec3 inside = clamp(f, vec3(0.0), vec3(dims - 1));
  float beyond = length(f - inside) * cell;
  ivec3 c = min(ivec3(floor(inside)), dims - 2);
  vec3 t = inside - vec3(c);
  int base = offset + c.x + dims.x * (c.y + dims.y * c.z);
  int dy = dims.x, dz = dims.x * dims.y;
  vec4 v = mix(mix(mix(headFieldNode(base), headFieldNode(base + 1), t.x),
                   mix(headFieldNode(base + dy), headFieldNode(base + dy + 1), t.x), t.y),
               mix(mix(headFieldNode(base + dz), headFieldNode(base + dz + 1), t.x),
                   mix(headFieldNode(base + dz + dy), headFieldNode(base + dz + dy + 1), t.x), t.y),
               t.z);
  v.w += beyond;
  return v;
}

#endif
