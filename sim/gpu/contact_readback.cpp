#include "sim/gpu/contact_readback.h"

#include <algorithm>
#include <bit>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "shaders/sim/bindings.glsl"
#include "sim/solver/contacts.h"

namespace csm::gpu {

std::vector<uint32_t> readCounters(const ContactSearch& g) {
  return g.counters().download<uint32_t>(CSM_COUNTERS);
}

std::vector<std::pair<uint32_t, uint32_t>> readPairs(const ContactSearch& g, bool* overflow) {
  const std::vector<uint32_t> c = readCounters(g);
  const size_t found = c[CSM_COUNTER_PAIR_LIST];
  if (overflow) *overflow = found > g.pairListCapacity();
  std::vector<std::pair<uint32_t, uint32_t>> out;
  for (const glm::uvec4& p :
       g.pairList().download<glm::uvec4>(std::min<size_t>(found, g.pairListCapacity())))
    if ((p.y >> CSM_CANDIDATE_SHIFT) & kPairNear)
      out.emplace_back(p.x, p.y & ((1u << CSM_CANDIDATE_SHIFT) - 1u));
  return out;
}

std::vector<std::vector<std::pair<uint32_t, float>>> readCandidates(const ContactSearch& g) {
  const size_t n = g.particles(), first = size_t(g.half()) * n;
  const std::vector<glm::uvec2> range = g.candidateRange().download<glm::uvec2>(2 * n);
  const std::vector<glm::uvec2> all =
      g.candidates(g.half()).download<glm::uvec2>(2 * size_t(g.pairListCapacity()));
  std::vector<std::vector<std::pair<uint32_t, float>>> out(n);
  for (size_t i = 0; i < n; ++i)
    for (uint32_t k = 0; k < range[first + i].y; ++k) {
      const glm::uvec2 c = all[range[first + i].x + k];
      out[i].emplace_back(c.x & ((1u << CSM_CANDIDATE_SHIFT) - 1u), std::bit_cast<float>(c.y));
    }
  return out;
}

std::vector<uint32_t> readSegmentOrder(const ContactSearch& g) {
  return g.segmentOrder().download<uint32_t>(g.particles());
}

}  // namespace csm::gpu
