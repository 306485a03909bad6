// What the solvers whose hair lives on the host share (CpuSolver and the baselines): the strands'
// layout and rest shape, the state in double and its one read, write, save, restore, copy and
// carry, the head handed before the reset, and the samples measured at once. Each solver adds its
// step; CpuSolver also keeps a rotation a region, saved and carried with the particles
// (saveMore, readMore, carryMore).
#pragma once

#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/base/state_bytes.h"
#include "sim/core/hair_state.h"
#include "sim/core/solver.h"
#include "sim/head/head_model.h"

namespace csm {

class HostSolver : public Solver, public SolverState, public SolverDiagnostics {
 public:
  void setHead(std::shared_ptr<const HeadModel> head) override { headModel_.hand(std::move(head)); }
  SolverCounts counts() const override { return {first_.size() - 1, x_.size()}; }
  double time() const override { return time_; }
  SolverState& state() override { return *this; }
  SolverDiagnostics& diagnostics() override { return *this; }

  void readPositions(std::vector<glm::vec4>& out) override;
  void readVelocities(std::vector<glm::vec4>& out) override;
  // The particles given overwrite the first of the state; more are ignored, fewer leave the
  // rest as they were.
  void write(const std::vector<glm::vec4>& positions,
             const std::vector<glm::vec4>& velocities) override;
  // The particle count, the positions and velocities in double, what saveMore adds, the clock
  // and the head.
  void save(SavedState& out) override;
  bool restore(const SavedState& in, std::string* error) override;
  // Read at once: the state is in memory.
  std::unique_ptr<FrameCopy> copyFrame(bool withState) override;
  void carry(const Pose& by) override;

  std::string failure() const override { return failure_; }
  // Measured at once (requestSample): the oldest one asked for.
  std::optional<FrameSample> takeSample(bool wait) override;
  void dropSamples() override { samples_.clear(); }

 protected:
  // The strands of `groom` laid out at rest under `head`, the clock at 0, no samples; says in
  // failure() when no head was handed. Returns the layout (for what a solver builds on it).
  HairState layOut(const Groom& groom, const Config& config, const Pose& head);
  // What else the next frames depend on (CpuSolver: each region's rotation): saved after the
  // velocities; read back in the same order, kept aside until the whole state has been read
  // (readMore: false when it cannot be) and then taken (restored, which also forgets what was
  // of the state before); turned with the hair when it is carried.
  virtual void saveMore(StateWriter& w) const { (void)w; }
  virtual bool readMore(StateReader& r) {
    (void)r;
    return true;
  }
  virtual void restored() {}
  virtual void carryMore(const Pose& by) { (void)by; }

  Config config_;
  SolverHead headModel_;  // the scene's head, handed before the reset
  std::string failure_;   // set by layOut when no head was handed
  double time_ = 0.0;
  Pose head_;   // the head pose at the end of the last step
  Pose torso_;  // the torso's there (where the step started, during a frame's first step)

  std::vector<uint32_t> first_{0};  // strand s: particles [first_[s], first_[s + 1])
  std::vector<uint32_t> strandOf_;
  std::vector<uint8_t> tipHeld_;  // per strand (HairState::tipHeld)
  std::vector<float> weight_;     // per strand (HairState::weight)
  double meanWeight_ = 1.0;       // of weight_ (contactRadius)
  std::vector<glm::dvec3> rest_;  // head frame
  std::vector<double> mass_;
  std::vector<double> restLength_;  // segment i -> i+1; 0 for a strand's last particle
  std::vector<glm::dvec3> x_, v_;
  std::deque<FrameSample> samples_;
};

}  // namespace csm
