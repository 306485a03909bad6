// Collision pass, grid build 2/3 (exclusive scan, level 3 of 3): each invocation rescans its
// block of counts from the block's offset, giving every bucket its first entry; entry
// `count` is the total, so bucket b's entries are [gridStart[b], gridStart[b+1]). The total
// also goes to the counters at `totalSlot` (when one is given), where GpuSolver reads the
// grid's to size the entry buffer.
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(std430, binding = CSM_BIND_GRID_COUNT) readonly buffer GridCount { uvec4 gridCount[]; };
layout(std430, binding = CSM_BIND_GRID_START) writeonly buffer GridStart { uvec4 gridStart[]; };
layout(std430, binding = CSM_BIND_SCAN_BLOCKS) readonly buffer ScanBlocks { uint blockSums[]; };
layout(std430, binding = CSM_BIND_COUNTERS) buffer Counters { uint counters[]; };

uniform uint blocks;
uniform uint totalSlot;  // a CSM_COUNTER_*, or CSM_COUNTERS for none

void main() {
  uint block = globalIndex();
  if (block >= blocks) return;
  uint first = block * uint(CSM_SCAN_LEAF / 4);
  uint running = blockSums[block];
  for (uint k = 0u; k < uint(CSM_SCAN_LEAF / 4); ++k) {
    uvec4 c = gridCount[first + k];
    uvec4 start = uvec4(running, running + c.x, running + c.x + c.y, running + c.x + c.y + c.z);
    gridStart[first + k] = start;
    running = start.w + c.w;
  }
  // The total after the last bucket (gridStart has one uvec4 more than the counts).
  if (block + 1u == blocks) {
    gridStart[first + uint(CSM_SCAN_LEAF / 4)] = uvec4(running);
    if (totalSlot < uint(CSM_COUNTERS)) counters[totalSlot] = running;
  }
}
