// Collision pass, grid build 3/6 (counting sort: exclusive scan, level 1): a work-efficient
// parallel scan (Blelloch 1990; GPU Gems 3, ch. 39) of each block of CSM_SCAN_BLOCK bucket
// counts in shared memory, writing the block-local exclusive prefix and the block's total.
#include "sim/common.glsl"

layout(local_size_x = CSM_SCAN_GROUP) in;

layout(std430, binding = CSM_BIND_GRID_COUNT) readonly buffer GridCount { uint gridCount[]; };
layout(std430, binding = CSM_BIND_GRID_START) writeonly buffer GridStart { uint gridStart[]; };
layout(std430, binding = CSM_BIND_SCAN_BLOCKS) writeonly buffer ScanBlocks { uint blockSums[]; };

uniform uint count;  // elements to scan

shared uint temp[CSM_SCAN_BLOCK];

void main() {
  uint block = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  uint lid = gl_LocalInvocationID.x;
  uint base = block * uint(CSM_SCAN_BLOCK);
  uint i0 = base + 2u * lid, i1 = i0 + 1u;
  temp[2u * lid] = i0 < count ? gridCount[i0] : 0u;
  temp[2u * lid + 1u] = i1 < count ? gridCount[i1] : 0u;
  // Up-sweep: partial sums in a balanced tree.
  uint offset = 1u;
  for (uint d = uint(CSM_SCAN_BLOCK) >> 1u; d > 0u; d >>= 1u) {
    barrier();
    if (lid < d) {
      uint ai = offset * (2u * lid + 1u) - 1u;
      uint bi = offset * (2u * lid + 2u) - 1u;
      temp[bi] += temp[ai];
    }
    offset <<= 1u;
  }
  barrier();
  if (lid == 0u) {
    blockSums[block] = temp[CSM_SCAN_BLOCK - 1];
    temp[CSM_SCAN_BLOCK - 1] = 0u;
  }
  // Down-sweep: each node passes its prefix to the left child, prefix + left to the right.
  for (uint d = 1u; d < uint(CSM_SCAN_BLOCK); d <<= 1u) {
    offset >>= 1u;
    barrier();
    if (lid < d) {
      uint ai = offset * (2u * lid + 1u) - 1u;
      uint bi = offset * (2u * lid + 2u) - 1u;
      uint t = temp[ai];
      temp[ai] = temp[bi];
      temp[bi] += t;
    }
  }
  barrier();
  if (i0 < count) gridStart[i0] = temp[2u * lid];
  if (i1 < count) gridStart[i1] = temp[2u * lid + 1u];
}
