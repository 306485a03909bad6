// What the render's compute passes share: one invocation per item, work groups of 64 laid
// out in two dimensions where one would pass the 65,535 groups a dimension may have.
#ifndef HAIR_COMPUTE_GLSL
#define HAIR_COMPUTE_GLSL
layout(local_size_x = 64) in;

uint invocationIndex() {
  return gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x +
         gl_GlobalInvocationID.x;
}
#endif  // HAIR_COMPUTE_GLSL
