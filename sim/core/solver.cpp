#include "sim/core/solver.h"

#include "sim/base/state_bytes.h"

namespace csm {

void Solver::carry(const Pose& by) {
  std::vector<glm::vec4> x, v;
  readPositions(x);
  readVelocities(v);
  for (glm::vec4& p : x) p = glm::vec4(glm::vec3(by.apply(glm::dvec3(glm::vec3(p)))), p.w);
  for (glm::vec4& u : v) u = glm::vec4(glm::vec3(by.rotation * glm::dvec3(glm::vec3(u))), u.w);
  writeState(x, v);
}

void Solver::saveState(SolverState& out) {
  std::vector<glm::vec4> x, v;
  readPositions(x);
  readVelocities(v);
  StateWriter w(out.bytes);
  w.put(particleCount());
  w.putVector(x);
  w.putVector(v);
}

namespace {

// A copy read when it was made (a solver whose state is in memory).
class ReadFrameCopy final : public FrameCopy {
 public:
  ReadFrameCopy(std::vector<glm::vec3> positions, SolverState state, bool withState)
      : positions_(std::move(positions)), state_(std::move(state)), withState_(withState) {}
  bool ready() const override { return true; }
  void read(std::vector<glm::vec3>& positions, SolverState* state) override {
    positions = positions_;
    if (state && withState_) *state = state_;
  }

 private:
  std::vector<glm::vec3> positions_;
  SolverState state_;
  bool withState_;
};

}  // namespace

std::unique_ptr<FrameCopy> Solver::copyFrame(bool withState) {
  std::vector<glm::vec4> x;
  readPositions(x);
  SolverState state;
  if (withState) saveState(state);
  return std::make_unique<ReadFrameCopy>(std::vector<glm::vec3>(x.begin(), x.end()),
                                         std::move(state), withState);
}

bool Solver::restoreState(const SolverState& in, std::string* error) {
  StateReader r(in.bytes);
  std::vector<glm::vec4> x, v;
  if (!r.expectCount(particleCount(), "particles", error) || !r.getVector(x, particleCount()) ||
      !r.getVector(v, particleCount()) || !r.done(error)) {
    if (error && error->empty()) *error = "a saved state of another size";
    return false;
  }
  writeState(x, v);
  return true;
}

}  // namespace csm
