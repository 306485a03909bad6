#include "sim/gpu/sample_ring.h"

#include <algorithm>
#include <bit>
#include <vector>

#include "shaders/sim/bindings.glsl"
#include "sim/gpu/contact_search.h"

namespace csm::gpu {

void SampleRing::request(long frame, uint32_t groups, const std::function<void()>& measure,
                         const gl::Buffer& records, const gl::Buffer& counters,
                         bool contactsMeasured) {
  if (pending_.size() == slots_.size()) {
    slots_[pending_.front()].fence.wait();
    ready_.push_back(readOldest());
  }
  int index = 0;
  while (std::find(pending_.begin(), pending_.end(), index) != pending_.end()) ++index;
  Slot& slot = slots_[index];
  slot.frame = frame;
  slot.groups = groups;
  slot.contactsMeasured = contactsMeasured;
  const GLsizeiptr recordBytes = GLsizeiptr(groups) * 2 * sizeof(glm::uvec4);
  const GLsizeiptr bytes = recordBytes + CSM_COUNTERS * sizeof(uint32_t);
  if (slot.staging.id() == 0) slot.staging = gl::Buffer();
  if (slot.staging.size() < bytes)
    slot.staging.setData(bytes, nullptr, gl::BufferUsage::StreamRead);
  if (groups > 0) {
    measure();
    gl::memoryBarrier(gl::Barrier::BufferUpdate);
    records.copyTo(slot.staging, 0, 0, recordBytes);
  }
  counters.copyTo(slot.staging, 0, recordBytes, CSM_COUNTERS * sizeof(uint32_t));
  slot.fence = gl::Fence::insert();
  pending_.push_back(index);
}

std::optional<FrameSample> SampleRing::take(bool wait) {
  if (!ready_.empty()) {
    FrameSample s = ready_.front();
    ready_.pop_front();
    return s;
  }
  if (pending_.empty()) return std::nullopt;
  const Slot& slot = slots_[pending_.front()];
  if (!slot.fence.passed()) {
    if (!wait) return std::nullopt;
    slot.fence.wait();
  }
  return readOldest();
}

FrameSample SampleRing::readOldest() {
  Slot& slot = slots_[pending_.front()];
  pending_.pop_front();
  std::vector<glm::uvec4> data(size_t(slot.groups) * 2 + CSM_COUNTERS / 4);
  slot.staging.read(0, GLsizeiptr(data.size() * sizeof(glm::uvec4)), data.data());
  // The records in order (measure.comp), as measureAccuracy adds them.
  FrameSample sample;
  sample.frame = slot.frame;
  sample.contactsMeasured = slot.contactsMeasured;
  Accuracy& a = sample.accuracy;
  uint32_t strainKey = 0;
  uint64_t segments = 0;
  double strainSum = 0.0;
  for (uint32_t g = 0; g < slot.groups; ++g) {
    const glm::uvec4 r0 = data[2 * g], r1 = data[2 * g + 1];
    strainKey = std::max(strainKey, r0.x);
    segments += r0.y;
    a.headPenetrations += r0.z;
    a.torsoPenetrations += r1.z;
    a.nanCount += r0.w;
    strainSum += double(std::bit_cast<float>(r1.x));
    a.maxSpeed = std::max(a.maxSpeed, double(std::bit_cast<float>(r1.y)));
  }
  if (segments > 0) {
    // measure.comp's orderedKey, inverted.
    const uint32_t bits = (strainKey & 0x80000000u) ? (strainKey & 0x7fffffffu) : ~strainKey;
    a.maxStrain = double(std::bit_cast<float>(bits));
    a.meanStrain = strainSum / double(segments);
  }
  const uint32_t* c = reinterpret_cast<const uint32_t*>(&data[size_t(slot.groups) * 2]);
  sample.contacts = contactStatsOf(c);
  return sample;
}

void SampleRing::drop() {
  pending_.clear();
  ready_.clear();
  for (Slot& slot : slots_) slot.fence = gl::Fence();
}

}  // namespace csm::gpu
