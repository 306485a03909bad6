#include "sim/gpu/strand_groups.h"

#include <algorithm>

namespace csm::gpu {

uint32_t groupParticlesFor(int longestStrand) {
  uint32_t size = kMinGroupParticles;
  while (size < uint32_t(std::max(longestStrand, 1))) size *= 2;
  return size;
}

std::vector<uint32_t> packStrandGroups(const std::vector<uint32_t>& strandFirst,
                                       uint32_t groupParticles) {
  std::vector<uint32_t> first;
  if (strandFirst.size() < 2) return {0};
  first.push_back(strandFirst.front());
  for (size_t s = 0; s + 1 < strandFirst.size(); ++s) {
    // Strand s ends at strandFirst[s + 1]: past the group's room, it opens the next group.
    if (strandFirst[s + 1] - first.back() > groupParticles) first.push_back(strandFirst[s]);
  }
  first.push_back(strandFirst.back());
  return first;
}

}  // namespace csm::gpu
