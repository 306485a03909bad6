#include "sim/gpu/contact_capacity.h"

#include <algorithm>

#include <glm/vec2.hpp>

namespace csm::gpu {
namespace {

// A capacity for `needed` items: a quarter more, never over `limit` (items of one buffer, a
// 32-bit index); 0 when `current` holds that already.
uint32_t grownCapacity(uint64_t needed, uint32_t current, uint64_t limit) {
  const uint64_t want = std::min(limit, needed + needed / 4);
  return want > current ? uint32_t(want) : 0;
}

}  // namespace

void ContactCapacity::setDevice(uint64_t textureTexels, uint64_t viewAlignment) {
  textureTexels_ = textureTexels;
  viewAlignment_ = std::max<uint64_t>(viewAlignment, 1);
}

uint32_t ContactCapacity::listSplit() const {
  const uint64_t step = std::max<uint64_t>(1, viewAlignment_ / sizeof(glm::uvec2));
  const uint64_t texels = std::min({textureTexels_, splitTexels_, uint64_t(1) << 31});
  return uint32_t(texels / step * step);
}

uint64_t ContactCapacity::entryLimit() const {
  // 16 bytes an entry, one RGBA32UI texel: 2 GiB at most, and what the device's views hold.
  return std::min({uint64_t(1) << 27, bufferBytes_ / 16, textureTexels_, budgetEntries()});
}

uint64_t ContactCapacity::pairLimit() const {
  // The sides and each frame's lists take two RG32UI texels a pair, in two views of
  // listSplit() texels each; the pair list one RGBA32UI texel a pair, within one view as
  // listSplit() is (16 bytes a pair each).
  return std::min({uint64_t(1) << 27, bufferBytes_ / 16, uint64_t(listSplit()), budgetPairs()});
}

uint64_t ContactCapacity::budgetEntries() const {
  return budgetBytes_ == UINT64_MAX ? UINT64_MAX : std::max<uint64_t>(1, budgetBytes_ / 4 / 16);
}

uint64_t ContactCapacity::budgetPairs() const {
  return budgetBytes_ == UINT64_MAX ? UINT64_MAX : std::max<uint64_t>(1, budgetBytes_ / 4 * 3 / 64);
}

bool ContactCapacity::growEntries(uint64_t needed) {
  const uint32_t want = grownCapacity(needed, entries_, entryLimit());
  if (want == 0) return false;
  entries_ = want;
  return true;
}

bool ContactCapacity::growPairs(uint64_t needed) {
  const uint32_t want = grownCapacity(needed, pairs_, pairLimit());
  if (want == 0) return false;
  pairs_ = want;
  return true;
}

}  // namespace csm::gpu
