// The GPU solver's SolverState: the hair's buffers read back, written, saved and restored bit for
// bit, copied behind a fence for a later read, and carried rigidly on the GPU (carry.comp).
#include <glm/gtc/quaternion.hpp>

#include "gl/fence.h"
#include "sim/base/state_bytes.h"
#include "sim/gpu/gpu_solver.h"

namespace csm {

void GpuSolver::readPositions(std::vector<glm::vec4>& out) {
  out = hair_.position.download<glm::vec4>(hair_.particles);
}

void GpuSolver::readVelocities(std::vector<glm::vec4>& out) {
  out = hair_.velocity.download<glm::vec4>(hair_.particles);
}

void GpuSolver::write(const std::vector<glm::vec4>& positions,
                      const std::vector<glm::vec4>& velocities) {
  if (hair_.particles == 0) return;
  std::vector<glm::vec4> x(positions), v(velocities);
  x.resize(hair_.particles, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  v.resize(hair_.particles, glm::vec4(0.0f));
  for (glm::vec4& p : x) p.w = 1.0f;
  hair_.position.upload(x);
  hair_.velocity.upload(v);
}

namespace {

// The GPU solver's state (save, and a frame copy's): the particle count, the positions,
// velocities and rotations the passes step, as the GPU holds them (float, bit for bit), the
// time and the head. restore reads it.
void writeGpuState(std::vector<std::byte>& bytes, const std::vector<glm::vec4>& position,
                   const std::vector<glm::vec4>& velocity, const std::vector<glm::vec4>& rotation,
                   double time, const Pose& head) {
  StateWriter w(bytes);
  w.put(position.size());
  w.putVector(position);
  w.putVector(velocity);
  w.putVector(rotation);
  w.put(time);
  w.put(head);
}

}  // namespace

void GpuSolver::save(SavedState& out) {
  const size_t n = hair_.particles;
  auto all = [n](const gl::Buffer& b) {
    return n ? b.download<glm::vec4>(n) : std::vector<glm::vec4>{};
  };
  writeGpuState(out.bytes, all(hair_.position), all(hair_.velocity), all(hair_.rotation), time_,
                head_);
}

namespace {

class GpuFrameCopy final : public FrameCopy {
 public:
  gl::Buffer staging{gl::NoCreate};
  gl::Fence fence;
  size_t particles = 0;
  bool withState = false;
  double time = 0.0;
  Pose head;

  bool ready() const override { return fence.passed(); }
  void read(std::vector<glm::vec3>& positions, SavedState* state) override {
    fence.wait();
    const size_t n = particles;
    const std::vector<glm::vec4> all =
        n ? staging.download<glm::vec4>(n * (withState ? 3 : 1)) : std::vector<glm::vec4>{};
    positions.assign(all.begin(), all.begin() + std::ptrdiff_t(n));
    if (!state || !withState) return;
    auto part = [&](size_t k) {
      return std::vector<glm::vec4>(all.begin() + std::ptrdiff_t(k * n),
                                    all.begin() + std::ptrdiff_t((k + 1) * n));
    };
    writeGpuState(state->bytes, part(0), part(1), part(2), time, head);
  }
};

}  // namespace

std::unique_ptr<FrameCopy> GpuSolver::copyFrame(bool withState) {
  auto copy = std::make_unique<GpuFrameCopy>();
  const size_t n = hair_.particles;
  const GLsizeiptr bytes = GLsizeiptr(n * sizeof(glm::vec4));
  copy->particles = n;
  copy->withState = withState;
  copy->time = time_;
  copy->head = head_;
  if (n > 0) {
    copy->staging = gl::Buffer(bytes * (withState ? 3 : 1), nullptr, gl::BufferUsage::StreamRead);
    gl::memoryBarrier(gl::Barrier::BufferUpdate);
    hair_.position.copyTo(copy->staging, 0, 0, bytes);
    if (withState) {
      hair_.velocity.copyTo(copy->staging, 0, bytes, bytes);
      hair_.rotation.copyTo(copy->staging, 0, 2 * bytes, bytes);
    }
  }
  copy->fence = gl::Fence::insert();
  return copy;
}

bool GpuSolver::restore(const SavedState& in, std::string* error) {
  const size_t n = hair_.particles;
  StateReader r(in.bytes);
  std::vector<glm::vec4> x, v, q;
  double time = 0.0;
  Pose head;
  if (!r.expectCount(n, "particles", error)) return false;
  if (!r.getVector(x, n) || !r.getVector(v, n) || !r.getVector(q, n) || !r.get(time) ||
      !r.get(head) || !r.done(error)) {
    if (error && error->empty()) *error = "a saved state of another solver";
    return false;
  }
  if (n > 0) {
    hair_.position.upload(x);
    hair_.velocity.upload(v);
    hair_.rotation.upload(q);
  }
  time_ = time;
  head_ = head;
  // Lists sized for the hair restored (a denser state than the reset's overflowed its first
  // frame), and no last list: the one kept is of another state, nothing to count crossings
  // against (as after a reset).
  if (listsCandidates()) sizeLists();
  measureAnew();
  return true;
}

void GpuSolver::carry(const Pose& by) {
  if (hair_.particles == 0) return;
  // Positions, velocities and each region's rotation (the warm start of its next extraction)
  // turn with the hair, on the GPU (carry.comp).
  const glm::dquat q = glm::normalize(by.rotation);
  hair_.bind();
  gl::memoryBarrier(gpu::kPassBarrier);
  passes_.carry.set("turn", glm::vec4(float(q.x), float(q.y), float(q.z), float(q.w)))
      .set("shift", glm::vec3(by.translation))
      .set("count", uint32_t(hair_.particles))
      .run(uint32_t(hair_.particles));
  gl::memoryBarrier(gl::Barrier::All);
  head_ = compose(by, head_);
}

}  // namespace csm
