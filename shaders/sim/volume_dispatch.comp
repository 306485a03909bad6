// The volume mode's node pass, its size (one invocation, after volume_splat.comp): the work
// groups for the nodes of the box the splat reached (volumeBox in common.glsl), laid out as
// dispatch_size.comp lays them out.
#include "sim/common.glsl"

layout(local_size_x = 1) in;

layout(binding = CSM_TEX_VOLUME_SUMS) uniform isamplerBuffer sumsTex;
layout(std430, binding = CSM_BIND_DISPATCH) writeonly buffer Dispatch { uvec4 dispatch[]; };

uniform uint groupSize;  // the node pass's local size

void main() {
  ivec3 low, high;
  ivec3 box = volumeBox(sumsTex, low, high);
  uint items = uint(box.x * box.y * box.z);
  uint groups = (items + groupSize - 1u) / groupSize;
  uint x = min(groups, 65535u);
  dispatch[CSM_DISPATCH_VOLUME_FIELD] = uvec4(x, x == 0u ? 0u : (groups + x - 1u) / x, 1u, 0u);
}
