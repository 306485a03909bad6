// A parallel loop over index ranges on all cores, run by one pool of threads that lives as
// long as the program (no thread is started or joined per loop). Each index is handled by
// exactly one chunk, and a chunk writes only its own outputs, so results do not depend on the
// thread count or on which thread ran a chunk.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>

namespace csm {

// The machine's cores, or fewer when the environment variable CSM_THREADS says so (read once).
size_t coreCount();

// Runs task(0) ... task(count - 1), each once, on the shared pool's threads and the calling
// one, and returns when all have finished. Called from inside a task, or while another thread
// holds the pool, it runs the tasks in order on the calling thread.
void runOnPool(size_t count, const std::function<void(size_t)>& task);

// Threads the shared pool has started so far (none until a loop needs them), for tests.
size_t poolThreadsStarted();

// Calls body(begin, end, chunk) on contiguous chunks of [0, count), chunk < coreCount().
// Runs inline when the work is too small to pay for waking the pool.
template <class Body>
void parallelChunks(size_t count, size_t minChunk, Body&& body) {
  const size_t chunks = std::min(coreCount(), count / std::max<size_t>(1, minChunk));
  if (chunks <= 1) {
    body(size_t(0), count, size_t(0));
    return;
  }
  runOnPool(chunks, [&](size_t c) { body(count * c / chunks, count * (c + 1) / chunks, c); });
}

// body(begin, end) over chunks of [0, count).
template <class Body>
void parallelFor(size_t count, size_t minChunk, Body&& body) {
  parallelChunks(count, minChunk, [&](size_t begin, size_t end, size_t) { body(begin, end); });
}

}  // namespace csm
