#pragma once
// A GL sync object (glFenceSync): marks the point in the command stream reached when it was
// inserted, so the CPU can ask, without waiting, whether the GPU has got that far. Reading a
// buffer the GPU finished writing behind a signalled fence does not stall the pipeline.
// Move-only; a default-constructed Fence holds no sync object.
#include <cstdint>

#include "gl/gl.h"

namespace csm::gl {

class Fence {
 public:
  Fence() noexcept = default;
  ~Fence();
  Fence(const Fence&) = delete;
  Fence& operator=(const Fence&) = delete;
  Fence(Fence&& other) noexcept;
  Fence& operator=(Fence&& other) noexcept;

  // A fence after everything issued so far; flushes, so that it is signalled eventually.
  static Fence insert();

  bool valid() const { return sync_ != nullptr; }
  // True once the GPU has passed it (without waiting). An empty fence is passed.
  bool passed() const;
  // Waits up to `timeoutNs` for it; true when passed. Counts a wait that had to block in
  // readbackStats().waits.
  bool wait(std::uint64_t timeoutNs = ~std::uint64_t(0)) const;
  // Waits for it, not counted: the drawing's own pacing (a software rasterizer's backlog).
  void waitUncounted() const;
  // Makes the current context's later commands wait for it on the GPU (glWaitSync): for a
  // fence from another context of the share group, without blocking the CPU. The fence's own
  // context must have flushed it (insert() does).
  void waitOnGpu() const;

 private:
  GLsync sync_ = nullptr;
};

// What the CPU has read back from the GPU since the last reset: Buffer::read and
// Framebuffer::read bytes and calls, and fence waits that blocked. For tests that a path
// reads nothing back, and for the metrics.
struct ReadbackStats {
  std::uint64_t bytes = 0;
  std::uint64_t reads = 0;
  std::uint64_t waits = 0;
};
ReadbackStats readbackStats();
void resetReadbackStats();
// Called by the wrappers that read (buffer.cpp, framebuffer.cpp, texture.cpp).
void countReadback(std::uint64_t bytes);
void countBlockingWait();

}  // namespace csm::gl
