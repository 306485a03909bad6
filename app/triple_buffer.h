// Positions handed from the simulation's GL context to the window's through three GPU buffers
// with fences: the simulation copies each finished frame into a buffer that is neither the one
// the window draws nor the latest one handed over, once the window's fence says its draws from
// that buffer are done; the window waits on the GPU (not the CPU) for the copy into the buffer it
// takes. Nothing is read back. Both sides may call from their own threads.
#pragma once

#include <array>
#include <cstddef>
#include <mutex>

#include "gl/buffer.h"
#include "gl/fence.h"

namespace csm {

class TripleBuffer {
 public:
  // The simulation's side, its context current: copies `bytes` of buffer `source` (written by
  // compute shaders) into a free buffer and returns its slot.
  int write(unsigned source, std::size_t bytes);
  // The slot written is the latest, to hand over; the caller publishes it with its frame in the
  // same critical section as the window reads that frame (hold), so the two agree.
  void publish(int slot);
  // The window's side: takes `slot` (its latest frame's) to draw from; the window's context
  // waits on the GPU for the copy into it.
  void hold(int slot);
  // After the draws from the held buffer are issued: a fence the next write waits for.
  void drawn();
  unsigned buffer(int slot) const;
  // Destroys the buffers and fences (with the simulation's context current).
  void release();

 private:
  struct Slot {
    gl::Buffer buffer{gl::NoCreate};
    gl::Fence written, read;
  };
  mutable std::mutex mutex_;
  std::array<Slot, 3> slots_;
  int latest_ = -1, held_ = -1;
};

}  // namespace csm
