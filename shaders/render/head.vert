// The head: one unit UV sphere, instanced once per head sphere. SHADOW_PASS draws it from
// the light into the head's depth map.
#include "render/frame.glsl"

layout(location = 0) in vec3 aPosition;  // on the unit sphere, so also the normal
layout(std430, binding = HEAD_SPHERES_BINDING) readonly buffer HeadSpheres {
  vec4 spheres[];  // xyz: world centre; w: radius
};

#ifdef SHADOW_PASS
void main() {
  vec4 s = spheres[gl_InstanceID];
  gl_Position = uLightViewProj * vec4(s.xyz + s.w * aPosition, 1.0);
}
#else
out vec3 vPosition;
out vec3 vNormal;
flat out int vSphere;
void main() {
  vec4 s = spheres[gl_InstanceID];
  vPosition = s.xyz + s.w * aPosition;
  vNormal = aPosition;  // a sphere's normal is its direction from the centre, in any frame
  vSphere = gl_InstanceID;
  gl_Position = uViewProj * vec4(vPosition, 1.0);
}
#endif
