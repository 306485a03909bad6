// Indirect dispatch sizes (ContactSearch::findCandidates), one invocation: the work groups a
// later pass needs for the items counter `counter` says this frame has, at most `capacity`
// (the pass itself checks what fits), laid out as ComputePass::run lays them out (a 2D grid of
// groups beyond 65535; globalIndex() flattens it). The pass then runs on what this frame
// found, not on its buffer's capacity.
#include "sim/common.glsl"

layout(local_size_x = 1) in;

layout(std430, binding = CSM_BIND_COUNTERS) readonly buffer Counters { uint counters[]; };
layout(std430, binding = CSM_BIND_DISPATCH) writeonly buffer Dispatch { uvec4 dispatch[]; };

uniform uint counter;    // a CSM_COUNTER_*
uniform uint capacity;   // items the pass's buffer holds
uniform uint groupSize;  // the pass's local size
uniform uint slot;       // a CSM_DISPATCH_*

void main() {
  uint items = min(counters[counter], capacity);
  uint groups = (items + groupSize - 1u) / groupSize;
  uint x = min(groups, 65535u);
  dispatch[slot] = uvec4(x, x == 0u ? 0u : (groups + x - 1u) / x, 1u, 0u);
}
