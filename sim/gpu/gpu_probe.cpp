#include "sim/gpu/gpu_probe.h"

#include <algorithm>

#include "gl/gl.h"
#include "sim/gpu/contact_readback.h"
#include "shaders/sim/bindings.glsl"

namespace csm {

ContactStats GpuProbe::readContactStats() const {
  return gpu::contactStatsOf(gpu::readCounters(solver_.contactSearch_).data());
}

void GpuProbe::detectContacts() {
  GpuSolver& s = solver_;
  if (s.hair_.particles == 0) return;
  s.reserveLists();
  // Timed as a frame of its own.
  s.timer_.beginFrame();
  s.listCandidatesNow(&s.timer_);
  // A tool asks for this pass's candidates: when the grid did not fit, grow it and run again
  // (stepFrame instead grows it as the next frame begins).
  if (s.contactSearch_.countersSeen(gpu::readCounters(s.contactSearch_).data())) {
    s.writeParams({s.head_}, {s.head_});
    s.bindAll();
    s.contactSearch_.findCandidates(&s.timer_);
  }
  s.timer_.endFrame();
  gl::memoryBarrier(gl::Barrier::All);
  s.framesSinceMeasure_ = 0;  // the counters measure the hair as it stands
}

void GpuProbe::limitGridStorage(uint64_t bytes) {
  solver_.contactSearch_.limitStorage(bytes);
}

void GpuProbe::limitGridListSplit(uint64_t texels) {
  solver_.contactSearch_.limitListSplit(texels);
}

uint32_t GpuProbe::gridListSplit() const {
  return solver_.contactSearch_.listSplit();
}

std::vector<std::pair<uint32_t, uint32_t>> GpuProbe::readContactPairs(bool* overflow) const {
  return gpu::readPairs(solver_.contactSearch_, overflow);
}

std::vector<std::vector<std::pair<uint32_t, float>>> GpuProbe::readCandidates() const {
  return gpu::readCandidates(solver_.contactSearch_);
}

std::vector<uint32_t> GpuProbe::readSegmentOrder() const {
  return gpu::readSegmentOrder(solver_.contactSearch_);
}

GpuProbe::GridStats GpuProbe::gridStats() const {
  const gpu::ContactSearch& search = solver_.contactSearch_;
  const std::vector<uint32_t> c = gpu::readCounters(search);
  GridStats g;
  g.entries = c[CSM_COUNTER_ENTRIES];
  g.capacity = search.entryCapacity();
  g.oversize = c[CSM_COUNTER_OVERSIZE];
  g.buckets = search.bucketCount();
  g.pairs = c[CSM_COUNTER_PAIR_LIST];
  g.pairCapacity = search.pairListCapacity();
  g.cell = solver_.params_.cellEdge;
  return g;
}

size_t GpuProbe::volumeNodes() const {
  return solver_.volume_.nodes();
}

size_t GpuProbe::volumeNodesVisited() const {
  return solver_.volume_.nodesVisited(solver_.contactSearch_.dispatch());
}

GpuKernels GpuProbe::kernels() const {
  return solver_.kernels_;
}

bool GpuProbe::setKernels(GpuKernels kernels, std::string* error) {
  GpuSolver& s = solver_;
  s.kernels_ = kernels;
  std::string why;
  if (!s.build(std::max(32, s.hair_.longestStrand), &why)) {
    if (error) *error = why;
    s.failure_ = why;
    return false;
  }
  return true;
}

}  // namespace csm
