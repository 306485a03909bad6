#include <atomic>
#include <numeric>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>

#include "sim/base/parallel.h"

using namespace csm;

TEST_CASE("the pool runs every index once and keeps its threads", "[parallel][quick]") {
  std::vector<int> hits(10000, 0);
  parallelFor(hits.size(), 16, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) ++hits[i];
  });
  const size_t started = poolThreadsStarted();
  CHECK(started <= coreCount() - 1);
  for (int round = 0; round < 200; ++round)
    parallelFor(hits.size(), 16, [&](size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i) ++hits[i];
    });
  for (int h : hits) REQUIRE(h == 201);
  // No thread per loop: the same pool ran all 201 loops.
  CHECK(poolThreadsStarted() == started);
}

TEST_CASE("chunks cover the range in order of chunk, nested loops run inline",
          "[parallel][quick]") {
  const size_t count = 1000;
  std::vector<size_t> chunkOf(count, size_t(-1));
  std::atomic<int> nested{0};
  parallelChunks(count, 1, [&](size_t begin, size_t end, size_t chunk) {
    for (size_t i = begin; i < end; ++i) chunkOf[i] = chunk;
    parallelFor(10, 1, [&](size_t b, size_t e) { nested += int(e - b); });
  });
  for (size_t i = 1; i < count; ++i) REQUIRE(chunkOf[i] >= chunkOf[i - 1]);
  CHECK(chunkOf.front() == 0);
  CHECK(chunkOf.back() == std::min(coreCount(), count) - 1);
  CHECK(nested == int(10 * std::min(coreCount(), count)));
}

TEST_CASE("loops from several threads at once all complete", "[parallel][quick]") {
  std::vector<std::thread> threads;
  std::vector<long> sums(4, 0);
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (int round = 0; round < 50; ++round) {
        std::vector<long> part(coreCount(), 0);
        parallelChunks(5000, 8, [&](size_t begin, size_t end, size_t chunk) {
          for (size_t i = begin; i < end; ++i) part[chunk] += long(i);
        });
        sums[t] += std::accumulate(part.begin(), part.end(), 0L);
      }
    });
  for (std::thread& th : threads) th.join();
  for (long s : sums) CHECK(s == 50L * 4999L * 5000L / 2);
}
