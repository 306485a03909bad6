// The body: a mesh in the head's frame, instanced once per placement (centre, scale; the turn of
// its part) of an SSBO from uPlacementBase on. For spheres, a unit sphere once per sphere (its
// position is its normal), each turned with its part; for the mannequin or head.mesh, the head's
// mesh once and the torso's once, each placed at the scalp centre where its part has it.
// SHADOW_PASS draws it from the light into the head's depth map.
#include "render/frame.glsl"

layout(location = 0) in vec3 aPosition;  // head frame, from the placement's centre
layout(location = 1) in vec3 aNormal;    // head frame
layout(std430, binding = CSM_RENDER_HEAD_SPHERES) readonly buffer HeadSpheres {
  // Two a placement: xyz the world centre, w the scale (a sphere's radius); the part's rotation
  // (a unit quaternion, xyz w).
  vec4 spheres[];
};
uniform int uPlacementBase;

int placement() {
  return uPlacementBase + gl_InstanceID;
}

vec3 turned(vec3 v) {
  vec4 q = spheres[2 * placement() + 1];
  vec3 t = 2.0 * cross(q.xyz, v);
  return v + q.w * t + cross(q.xyz, t);
}

vec3 worldPosition() {
  vec4 s = spheres[2 * placement()];
  return s.xyz + s.w * turned(aPosition);
}

#ifdef SHADOW_PASS
void main() {
  gl_Position = uLightViewProj * vec4(worldPosition(), 1.0);
}
#else
out vec3 vPosition;
out vec3 vNormal;
out vec3 vScalpDir;  // head frame: where on the scalp map (from the placement's centre)
flat out int vSphere;
void main() {
  vPosition = worldPosition();
  vNormal = turned(aNormal);
  vScalpDir = aPosition;
  vSphere = placement();
  gl_Position = uViewProj * vec4(vPosition, 1.0);
}
#endif
