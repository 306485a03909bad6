// A parallel loop over index ranges on all cores. Each index is handled by exactly one thread
// and writes only its own outputs, so results do not depend on the thread count.
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace csm {

inline size_t coreCount() {
  return std::max(1u, std::thread::hardware_concurrency());
}

// Calls body(begin, end, chunk) on contiguous chunks of [0, count), chunk < coreCount(), in
// order of chunk. Runs inline when the work is too small to pay for starting threads.
template <class Body>
void parallelChunks(size_t count, size_t minChunk, Body&& body) {
  const size_t chunks = std::min(coreCount(), count / std::max<size_t>(1, minChunk));
  if (chunks <= 1) {
    body(size_t(0), count, size_t(0));
    return;
  }
  std::vector<std::thread> threads;
  threads.reserve(chunks - 1);
  for (size_t c = 1; c < chunks; ++c)
    threads.emplace_back([&, c] { body(count * c / chunks, count * (c + 1) / chunks, c); });
  body(size_t(0), count / chunks, size_t(0));
  for (std::thread& t : threads) t.join();
}

// body(begin, end) over chunks of [0, count).
template <class Body>
void parallelFor(size_t count, size_t minChunk, Body&& body) {
  parallelChunks(count, minChunk, [&](size_t begin, size_t end, size_t) { body(begin, end); });
}

}  // namespace csm
