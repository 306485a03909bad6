// Multiplies every element of binding 0 by FACTOR (× 2 unless defined): the GL tests'
// smallest compute shader.
#include "test/common.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 0) buffer Values { float values[]; };

uniform uint count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < count) values[i] = scale(values[i]);
}
