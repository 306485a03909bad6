// Frame samples taken without stalling: each request copies the measure pass's records and
// the collision counters into a staging buffer of a small ring and fences it; a sample is read
// once its fence has passed, a few frames later. A full ring waits for its oldest slot.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>

#include "gl/buffer.h"
#include "gl/fence.h"
#include "sim/core/results.h"

namespace csm::gpu {

class SampleRing {
 public:
  // Copies `groups` measure records (two uvec4 each) and the counters, then fences. `measure`
  // runs the measure pass first (only when there are records).
  void request(long frame, uint32_t groups, const std::function<void()>& measure,
               const gl::Buffer& records, const gl::Buffer& counters, bool contactsMeasured);
  std::optional<FrameSample> take(bool wait);
  void drop();
  // The bytes of its staging buffers.
  uint64_t bytes() const {
    uint64_t sum = 0;
    for (const Slot& s : slots_) sum += uint64_t(s.staging.size());
    return sum;
  }

 private:
  struct Slot {
    gl::Buffer staging{gl::NoCreate};
    gl::Fence fence;
    long frame = -1;
    uint32_t groups = 0;
    bool contactsMeasured = false;  // the counters hold a candidate list's measures
  };
  static constexpr int kSlots = 4;
  FrameSample readOldest();  // its fence has passed

  std::array<Slot, kSlots> slots_;
  std::deque<int> pending_;        // oldest first
  std::deque<FrameSample> ready_;  // read off a full ring, not taken yet
};

}  // namespace csm::gpu
