// The GPU solver's SolverDiagnostics: the measures of a frame reduced on the GPU and read a few
// frames late (SampleRing), the contact measures' searches outside the frames' timing, the
// memory it holds.
#include <algorithm>

#include "gl/draw.h"
#include "sim/gpu/gpu_solver.h"
#include "shaders/sim/bindings.glsl"

namespace csm {

MemoryUse GpuSolver::memoryUse() const {
  MemoryUse m;
  m.bytes = {{"strands", hair_.bytes()},
             {"contacts", contactSearch_.bytes() + contactSolve_.bytes()},
             {"volume", volume_.bytes()},
             {"head and parameters", uint64_t(headField_.size() + paramsBuffer_.size() +
                                              spheres_.size() + measure_.size())},
             {"samples", samples_.bytes()}};
  return m;
}

void GpuSolver::setContactMeasures(bool always) {
  const bool listed = listsCandidates(), was = measureContacts_;
  measureContacts_ = always;
  if (!listed && listsCandidates()) sizeLists();
  if (always && !was) measureAnew();
}

void GpuSolver::measureAnew() {
  framesSinceMeasure_ = 2;
  if (measureContacts_ && !strandContacts(config_.collision.mode)) measureNow();
}

void GpuSolver::measureNow() {
  if (hair_.particles == 0 || !failure_.empty()) return;
  listCandidatesNow(nullptr);
  gl::memoryBarrier(gl::Barrier::All);
  framesSinceMeasure_ = 0;
}

unsigned GpuSolver::lastSubstepSpheres() const {
  // The spheres buffer holds the head's spheres for each step of the last writeParams: the
  // measures use the last step's.
  const size_t perStep = shape_.spheres.size() + shape_.torsoSpheres.size();
  if (perStep == 0) return 0;
  const size_t uploaded = size_t(spheres_.size()) / sizeof(glm::vec4);
  return unsigned(uploaded - std::min(uploaded, perStep));
}

void GpuSolver::requestSample(long frame) {
  const bool listed = strandContacts(config_.collision.mode);
  // With hair-hair off, the contact measures are of where this frame started, as a strand
  // mode's list measures it: the search made when the last frame ended (after its sample, or
  // when the measures or the settings changed). With frames stepped since and no sample
  // between, of where this one ends (the crossings of the frames before it that no sample
  // reported are lost).
  const bool measuring = !listed && measureContacts_ && hair_.particles > 0;
  if (measuring && framesSinceMeasure_ > 1) measureNow();
  const uint32_t groups = uint32_t((hair_.particles + CSM_MEASURE_GROUP - 1) / CSM_MEASURE_GROUP);
  samples_.request(
      frame, groups,
      [&] {
        bindAll();
        passes_.measure.set("sphereBase", lastSubstepSpheres())
            .set("lastStep", unsigned(std::max(substepsWritten_ - 1, 0)))
            .run(uint32_t(hair_.particles));
      },
      measure_, contactSearch_.counters(), listed || measureContacts_);
  // The next frame's start, searched here, outside its timing (the sample has its copy).
  if (measuring && framesSinceMeasure_ != 0) measureNow();
}

std::optional<FrameSample> GpuSolver::takeSample(bool wait) {
  std::optional<FrameSample> sample = samples_.take(wait);
  if (sample && sample->contactsMeasured)
    sample->contacts.measureStride = contactSearch_.measureStride();
  return sample;
}

void GpuSolver::finish() {
  gl::finish();
}

}  // namespace csm
