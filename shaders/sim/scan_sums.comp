// Collision pass, grid build 2/3 (exclusive scan, level 2 of 3): one work group scans the
// block sums in place with a work-efficient parallel scan in shared memory (Blelloch 1990;
// GPU Gems 3, ch. 39), CSM_SCAN_BLOCK at a time with a running carry (one round covers
// CSM_SCAN_BLOCK x CSM_SCAN_LEAF = 32768 buckets; 100k strands need a few), and stores the
// grand total after them.
#include "sim/common.glsl"

layout(local_size_x = CSM_SCAN_GROUP) in;

layout(std430, binding = CSM_BIND_SCAN_BLOCKS) buffer ScanBlocks { uint blockSums[]; };

uniform uint count;  // blocks

shared uint temp[CSM_SCAN_BLOCK];
shared uint carry;

void main() {
  uint lid = gl_LocalInvocationID.x;
  if (lid == 0u) carry = 0u;
  for (uint base = 0u; base < count; base += uint(CSM_SCAN_BLOCK)) {
    uint i0 = base + 2u * lid, i1 = i0 + 1u;
    barrier();
    temp[2u * lid] = i0 < count ? blockSums[i0] : 0u;
    temp[2u * lid + 1u] = i1 < count ? blockSums[i1] : 0u;
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
    uint total = temp[CSM_SCAN_BLOCK - 1];
    barrier();
    if (lid == 0u) temp[CSM_SCAN_BLOCK - 1] = 0u;
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
    if (i0 < count) blockSums[i0] = temp[2u * lid] + carry;
    if (i1 < count) blockSums[i1] = temp[2u * lid + 1u] + carry;
    barrier();
    if (lid == 0u) carry += total;
  }
  barrier();
  if (lid == 0u) blockSums[count] = carry;
}
