// The head's distance field (sim/head/distance_grid.h) as the solver's passes read it: its nodes
// through storage or a buffer texture, its layout from the parameter block, the sample itself
// head_field_sample.glsl's (the follower pass reads the same).
#ifdef CSM_STORAGE_READS
layout(std430, binding = CSM_BIND_HEAD_FIELD) readonly buffer HeadFieldIn { vec4 headFieldIn[]; };
#define headFieldNode(i) headFieldIn[uint(i)]
#else
layout(binding = CSM_TEX_HEAD_FIELD) uniform samplerBuffer headFieldTex;
#define headFieldNode(i) texelFetch(headFieldTex, i)
#endif
#include "sim/head_field_sample.glsl"

bool headIsField() {
  return P.headIsField != 0u;
}

// Gradient (xyz, not normalised) and distance (w) at p, head frame (head_field_sample.glsl).
vec4 headFieldSample(vec3 p) {
  return headFieldAt(ivec3(P.headFieldDims), P.headFieldOrigin, P.headFieldCell, p);
}

// A world point in the frame of a head at pose `head` (a rigid transform).
vec3 toHeadFrame(mat4 head, vec3 x) {
  return transpose(mat3(head)) * (x - head[3].xyz);
}
