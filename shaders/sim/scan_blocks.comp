// Collision pass, grid build 2/3 (counting sort: exclusive scan, level 1 of 3). A two-level
// parallel scan (reduce, scan the partial sums, then scan-and-add; Merrill & Grimshaw 2011
// call the sequential leaves "raking"): each invocation sums a block of CSM_SCAN_LEAF
// consecutive bucket counts; scan_sums.comp scans the block sums, scan_add.comp rescans
// each block from its offset. Sequential leaves need no shared memory and no barriers, which
// llvmpipe runs as coroutine switches per SIMD group; the work stays O(buckets) and the
// depth O(leaf + log(blocks)).
#include "sim/common.glsl"

layout(local_size_x = CSM_PARTICLE_GROUP) in;

layout(std430, binding = CSM_BIND_GRID_COUNT) readonly buffer GridCount { uvec4 gridCount[]; };
layout(std430, binding = CSM_BIND_SCAN_BLOCKS) writeonly buffer ScanBlocks { uint blockSums[]; };

uniform uint blocks;

void main() {
  uint block = globalIndex();
  if (block >= blocks) return;
  // The bucket count is a power of two >= 64 and CSM_SCAN_LEAF divides it.
  uint first = block * uint(CSM_SCAN_LEAF / 4);
  uvec4 sum = uvec4(0u);
  for (uint k = 0u; k < uint(CSM_SCAN_LEAF / 4); ++k) sum += gridCount[first + k];
  blockSums[block] = sum.x + sum.y + sum.z + sum.w;
}
