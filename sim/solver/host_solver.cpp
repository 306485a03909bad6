#include "sim/solver/host_solver.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "sim/solver/contacts.h"

namespace csm {
namespace {

// A copy read when it was made.
class HostFrameCopy final : public FrameCopy {
 public:
  HostFrameCopy(std::vector<glm::vec3> positions, SavedState state, bool withState)
      : positions_(std::move(positions)), state_(std::move(state)), withState_(withState) {}
  bool ready() const override { return true; }
  void read(std::vector<glm::vec3>& positions, SavedState* state) override {
    positions = positions_;
    if (state && withState_) *state = state_;
  }

 private:
  std::vector<glm::vec3> positions_;
  SavedState state_;
  bool withState_;
};

}  // namespace

HairState HostSolver::layOut(const Groom& groom, const Config& config, const Pose& head) {
  config_ = config;
  failure_ = headModel_.handed() ? std::string() : std::string(kNoHeadFailure);
  time_ = 0.0;
  head_ = head;
  HairState st = makeHairState(groom, config.sim, head);
  const size_t n = st.particleCount();
  first_ = st.strandFirst;
  strandOf_ = st.particleStrand;
  tipHeld_ = st.tipHeld;
  weight_ = st.weight;
  meanWeight_ = meanWeight(weight_);
  rest_.resize(n);
  mass_.resize(n);
  x_.resize(n);
  for (size_t i = 0; i < n; ++i) {
    rest_[i] = glm::dvec3(glm::vec3(st.rest[i]));
    mass_[i] = st.rest[i].w;
    x_[i] = head.apply(rest_[i]);
  }
  restLength_.assign(n, 0.0);
  for (size_t i = 0; i + 1 < n; ++i)
    if (strandOf_[i] == strandOf_[i + 1]) restLength_[i] = glm::length(rest_[i + 1] - rest_[i]);
  v_.assign(n, glm::dvec3(0.0));
  samples_.clear();
  return st;
}

void HostSolver::readPositions(std::vector<glm::vec4>& out) {
  out.resize(x_.size());
  for (size_t i = 0; i < x_.size(); ++i) out[i] = glm::vec4(glm::vec3(x_[i]), 1.0f);
}

void HostSolver::readVelocities(std::vector<glm::vec4>& out) {
  out.resize(v_.size());
  for (size_t i = 0; i < v_.size(); ++i) out[i] = glm::vec4(glm::vec3(v_[i]), 0.0f);
}

void HostSolver::write(const std::vector<glm::vec4>& positions,
                       const std::vector<glm::vec4>& velocities) {
  for (size_t i = 0; i < x_.size() && i < positions.size(); ++i)
    x_[i] = glm::dvec3(glm::vec3(positions[i]));
  for (size_t i = 0; i < v_.size() && i < velocities.size(); ++i)
    v_[i] = glm::dvec3(glm::vec3(velocities[i]));
}

void HostSolver::save(SavedState& out) {
  StateWriter w(out.bytes);
  w.put(x_.size());
  w.putVector(x_);
  w.putVector(v_);
  saveMore(w);
  w.put(time_);
  w.put(head_);
}

bool HostSolver::restore(const SavedState& in, std::string* error) {
  StateReader r(in.bytes);
  std::vector<glm::dvec3> x, v;
  double time = 0.0;
  Pose head;
  if (!r.expectCount(x_.size(), "particles", error)) return false;
  if (!r.getVector(x, x_.size()) || !r.getVector(v, x_.size()) || !readMore(r) || !r.get(time) ||
      !r.get(head) || !r.done(error)) {
    if (error && error->empty()) *error = "a saved state of another solver";
    return false;
  }
  x_ = std::move(x);
  v_ = std::move(v);
  time_ = time;
  head_ = head;
  restored();
  return true;
}

std::unique_ptr<FrameCopy> HostSolver::copyFrame(bool withState) {
  std::vector<glm::vec3> positions(x_.size());
  for (size_t i = 0; i < x_.size(); ++i) positions[i] = glm::vec3(x_[i]);
  SavedState state;
  if (withState) save(state);
  return std::make_unique<HostFrameCopy>(std::move(positions), std::move(state), withState);
}

void HostSolver::carry(const Pose& by) {
  for (glm::dvec3& p : x_) p = by.apply(p);
  for (glm::dvec3& u : v_) u = by.rotation * u;
  carryMore(by);
  head_ = compose(by, head_);
}

std::optional<FrameSample> HostSolver::takeSample(bool) {
  if (samples_.empty()) return std::nullopt;
  FrameSample s = samples_.front();
  samples_.pop_front();
  return s;
}

}  // namespace csm
