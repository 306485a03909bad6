// Collision pass, grid build 5/6 (exclusive scan, level 3): adds each block's offset to its
// elements, giving every bucket its first entry; entry `count` is the total, so bucket b's
// entries are [gridStart[b], gridStart[b+1]).
#include "sim/common.glsl"

layout(local_size_x = CSM_SCAN_GROUP) in;

layout(std430, binding = CSM_BIND_GRID_START) buffer GridStart { uint gridStart[]; };
layout(std430, binding = CSM_BIND_SCAN_BLOCKS) readonly buffer ScanBlocks { uint blockSums[]; };

uniform uint count;   // elements
uniform uint blocks;  // scan blocks

void main() {
  uint i = globalIndex();
  if (i < count) gridStart[i] += blockSums[i / uint(CSM_SCAN_BLOCK)];
  if (i == 0u) gridStart[count] = blockSums[blocks];
}
