// The hair moved rigidly with a head that jumped (GpuSolver::carry, HostSolver::carry on the CPU):
// one invocation per particle, its position turned by `turn` (a quaternion, x y z w) about the
// origin and moved by `shift`, its velocity turned, and its region's rotation turned (the warm
// start of its next extraction). On the GPU: nothing read back.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(std430, binding = CSM_BIND_POSITION) buffer Position { vec4 pos[]; };
layout(std430, binding = CSM_BIND_VELOCITY) buffer Velocity { vec4 vel[]; };
layout(std430, binding = CSM_BIND_ROTATION) buffer Rotation { vec4 rotation[]; };

uniform vec4 turn;
uniform vec3 shift;
uniform uint count;  // particles (the parameter block may not be written yet)

void main() {
  uint i = globalIndex();
  if (i >= count) return;
  mat3 R = quatToMat(turn);
  pos[i] = vec4(R * pos[i].xyz + shift, pos[i].w);
  vel[i] = vec4(R * vel[i].xyz, vel[i].w);
  rotation[i] = normalize(quatMul(turn, rotation[i]));
}
