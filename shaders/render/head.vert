// The head: a mesh in the head's frame, instanced once per placement (centre, scale) of an
// SSBO and turned by the head's rotation. For spheres, a unit sphere once per head sphere
// (its position is its normal); for the mannequin, its mesh once, placed at its scalp centre.
// SHADOW_PASS draws it from the light into the head's depth map.
#include "render/frame.glsl"

layout(location = 0) in vec3 aPosition;  // head frame, from the placement's centre
layout(location = 1) in vec3 aNormal;    // head frame
layout(std430, binding = CSM_RENDER_HEAD_SPHERES) readonly buffer HeadSpheres {
  vec4 spheres[];  // xyz: world centre; w: scale (a sphere's radius)
};

vec3 worldPosition() {
  vec4 s = spheres[gl_InstanceID];
  return s.xyz + s.w * (mat3(uHeadRotation) * aPosition);
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
  vNormal = mat3(uHeadRotation) * aNormal;
  vScalpDir = aPosition;
  vSphere = gl_InstanceID;
  gl_Position = uViewProj * vec4(vPosition, 1.0);
}
#endif
