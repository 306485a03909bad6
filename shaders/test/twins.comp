// One GLSL function of the solver on many inputs, for tests/gpu/twins_test.cpp, which runs its
// C++ twin on the same inputs (sim/solver/cpu_steps.h lists the pairs). One define picks the
// function; inputs are `inputs` vec4s an item, outputs `outputs` vec4s an item, as each section
// says. The parameter block P (common.glsl) holds what the functions read of it; the head's
// spheres and field are bound where the passes bind them.
#include "sim/common.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer In { vec4 inputs[]; };
layout(std430, binding = 1) writeonly buffer Out { vec4 outputs[]; };
layout(std430, binding = CSM_BIND_SPHERES) readonly buffer Spheres { vec4 spheres[]; };

uniform uint items;

#if defined(TWIN_FIELD_SAMPLE) || defined(TWIN_FIELD_PUSH)
#define CSM_HEAD_FIELD
#endif
#include "sim/head_push.glsl"
#ifdef TWIN_WIND
#include "sim/wind.glsl"
#endif

void main() {
  uint i = globalIndex();
  if (i >= items) return;
#if defined(TWIN_WIND)
  // In: x (xyz), t (w). Out: the wind's velocity.
  vec4 a = inputs[i];
  outputs[i] = vec4(windVelocity(a.xyz, a.w), 0.0);
#elif defined(TWIN_ROTATION)
  // In: A's columns, (1 / J, iterations, twistStep, -), q, axis. Out: q.
  vec4 c0 = inputs[6u * i], c1 = inputs[6u * i + 1u], c2 = inputs[6u * i + 2u];
  vec4 k = inputs[6u * i + 3u];
  outputs[i] = extractRotation(mat3(c0.xyz, c1.xyz, c2.xyz), k.x, inputs[6u * i + 4u], int(k.y),
                               inputs[6u * i + 5u].xyz, k.z);
#elif defined(TWIN_SPHERE)
  // In: p, prev, the sphere (centre, radius), (maxLength, -, -, -). Out: p, (moved, -, -, -).
  vec3 p = inputs[4u * i].xyz;
  vec4 sp = inputs[4u * i + 2u];
  bool moved = pushOutOfSphere(p, inputs[4u * i + 1u].xyz, sp.xyz, sp.w, inputs[4u * i + 3u].x);
  outputs[2u * i] = vec4(p, 0.0);
  outputs[2u * i + 1u] = vec4(moved ? 1.0 : 0.0);
#elif defined(TWIN_HEAD_SPHERES) || defined(TWIN_FIELD_PUSH)
  // In: p, prev, (r, maxLength, -, -). Out: p, (touching, -, -, -), the field's normal.
  vec3 p = inputs[3u * i].xyz, prev = inputs[3u * i + 1u].xyz;
  vec4 k = inputs[3u * i + 2u];
  vec3 normal = vec3(0.0);
#ifdef TWIN_FIELD_PUSH
  bool touching = pushOutOfFieldHead(p, prev, S[0], k.x, k.y, normal);
#else
  bool touching = pushOutOfHead(p, prev, 0u, k.x, k.y);
#endif
  outputs[3u * i] = vec4(p, 0.0);
  outputs[3u * i + 1u] = vec4(touching ? 1.0 : 0.0);
  outputs[3u * i + 2u] = vec4(normal, 0.0);
#elif defined(TWIN_FIELD_SAMPLE)
  // In: p (head frame). Out: the gradient (xyz) and the distance (w).
  outputs[i] = headFieldSample(inputs[i].xyz);
#elif defined(TWIN_LIMIT)
  // In: x, v, anchor, (restLength, h, -, -). Out: x, v, (moved, -, -, -).
  vec3 x = inputs[4u * i].xyz, v = inputs[4u * i + 1u].xyz;
  vec4 k = inputs[4u * i + 3u];
  bool moved = limitToward(x, v, inputs[4u * i + 2u].xyz, k.x, k.y);
  outputs[3u * i] = vec4(x, 0.0);
  outputs[3u * i + 1u] = vec4(v, 0.0);
  outputs[3u * i + 2u] = vec4(moved ? 1.0 : 0.0);
#elif defined(TWIN_HASH)
  // In: (strand, stride) as floats. Out: (in the sample, -, -, -).
  outputs[i] = vec4(inMeasureSample(uint(inputs[i].x), uint(inputs[i].y)) ? 1.0 : 0.0);
#endif
}
