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
  return headFieldAt(ivec3(P.headFieldDims), P.headFieldOrigin, P.headFieldCell, p, 0);
}

// The same of the torso's field, torso frame.
vec4 torsoFieldSample(vec3 p) {
  return headFieldAt(ivec3(P.torsoFieldDims), P.torsoFieldOrigin, P.torsoFieldCell, p,
                     int(P.torsoFieldOffset));
}

// A world point in the frame of a head at pose `head` (a rigid transform).
vec3 toHeadFrame(mat4 head, vec3 x) {
  return transpose(mat3(head)) * (x - head[3].xyz);
}

// The body's field at world point x, the union of its parts (bodySample in
// sim/solver/cpu_steps.cpp): the nearer part's outward gradient (world, not normalised) and
// distance; `part` 0 the head, 1 the torso.
vec4 bodySample(Substep st, vec3 x, out int part) {
  vec4 s = headFieldSample(toHeadFrame(st.head, x));
  s.xyz = mat3(st.head) * s.xyz;
  part = 0;
  if (P.torsoIsField != 0u) {
    vec4 t = torsoFieldSample(quatUnturn(st.torsoRotation, x - st.torsoTranslation.xyz));
    if (t.w < s.w) {
      s = vec4(quatTurn(st.torsoRotation, t.xyz), t.w);
      part = 1;
    }
  }
  return s;
}
vec4 bodySample(Substep st, vec3 x) {
  int part;
  return bodySample(st, x, part);
}
