// FNV-1a, 64 bits: the hash a shot's cache keeps of its files, its inputs and its groom. A hash
// of several pieces is the hash of the first carried on over the next (`h` from the call before).
#pragma once

#include <cstddef>
#include <cstdint>

namespace csm {

inline constexpr uint64_t kFnv1aOffset = 14695981039346656037ull;

inline uint64_t fnv1a(const void* data, size_t size, uint64_t h = kFnv1aOffset) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < size; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}

}  // namespace csm
