// printf into a std::string, whatever its length: the labels and lines the torture map and the
// benchmarks print (GCC 12 warns falsely on chains of string +).
#pragma once

#include <cstdio>
#include <string>

namespace csm {

template <class... A>
std::string format(const char* f, A... a) {
  const int n = std::snprintf(nullptr, 0, f, a...);
  if (n <= 0) return {};
  std::string out(size_t(n) + 1, '\0');
  std::snprintf(out.data(), out.size(), f, a...);
  out.resize(size_t(n));
  return out;
}

}  // namespace csm
