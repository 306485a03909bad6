// Random numbers that are a function of their inputs: the same seed, strand and draw give the
// same number on every machine and in any order of computation (no generator state to share).
#pragma once

#include <cstdint>

namespace csm {

// SplitMix64's finaliser: a small, well-mixed hash.
inline uint64_t mix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// Uniform in [0, 1): the k-th number of strand `strand` under `seed`.
inline double random01(uint64_t seed, uint64_t strand, uint64_t k) {
  const uint64_t h = mix64(mix64(mix64(seed) ^ strand) ^ (k * 0x632be59bd9b4e019ull));
  return double(h >> 11) * (1.0 / 9007199254740992.0);
}

}  // namespace csm
