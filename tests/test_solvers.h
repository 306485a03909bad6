// Solvers for tests of what the callers do with a solver that misbehaves or is slow: the CPU
// solver with one thing changed (WrappedSolver: every call goes to the CPU solver inside; a test
// overrides what it changes), its positions turning to NaN (NanAfter), its frames held back
// (GatedSolver).
#pragma once

#include <atomic>
#include <cmath>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/solver/cpu_solver.h"

namespace csm::test {

class WrappedSolver : public Solver, public SolverState, public SolverDiagnostics {
 public:
  std::string_view name() const override { return inner_.name(); }
  void setHead(std::shared_ptr<const HeadModel> head) override { inner_.setHead(std::move(head)); }
  void reset(const Groom& g, const Config& c, const Pose& h) override { inner_.reset(g, c, h); }
  void setConfig(const Config& c) override { inner_.setConfig(c); }
  using Solver::stepFrame;
  void stepFrame(const FramePath& path) override { inner_.stepFrame(path); }
  SolverCounts counts() const override { return inner_.counts(); }
  double time() const override { return inner_.time(); }
  SolverState& state() override { return *this; }
  SolverDiagnostics& diagnostics() override { return *this; }

  void readPositions(std::vector<glm::vec4>& out) override { inner_.readPositions(out); }
  void readVelocities(std::vector<glm::vec4>& out) override { inner_.readVelocities(out); }
  void write(const std::vector<glm::vec4>& x, const std::vector<glm::vec4>& v) override {
    inner_.write(x, v);
  }
  void save(SavedState& out) override { inner_.save(out); }
  bool restore(const SavedState& in, std::string* error) override {
    return inner_.restore(in, error);
  }
  std::unique_ptr<FrameCopy> copyFrame(bool withState) override {
    return inner_.copyFrame(withState);
  }
  void carry(const Pose& by) override { inner_.carry(by); }

  std::string failure() const override { return inner_.failure(); }
  void requestSample(long frame) override { inner_.requestSample(frame); }
  std::optional<FrameSample> takeSample(bool wait) override { return inner_.takeSample(wait); }
  void dropSamples() override { inner_.dropSamples(); }
  void setContactMeasures(bool always) override { inner_.setContactMeasures(always); }
  std::vector<StageTime> stageTimes() override { return inner_.stageTimes(); }
  StiffnessInfo stiffness() const override { return inner_.stiffness(); }

 protected:
  CpuSolver inner_;
};

// A CPU solver whose positions turn to NaN after `badFrame` frames: what a blown-up
// simulation looks like to the viewer.
class NanAfter final : public WrappedSolver {
 public:
  explicit NanAfter(long badFrame) : badFrame_(badFrame) {}
  std::string_view name() const override { return "nan-after"; }
  void reset(const Groom& g, const Config& c, const Pose& h) override {
    frames_ = 0;
    inner_.reset(g, c, h);
  }
  using Solver::stepFrame;
  void stepFrame(const FramePath& path) override {
    ++frames_;
    inner_.stepFrame(path);
  }
  void readPositions(std::vector<glm::vec4>& out) override {
    inner_.readPositions(out);
    if (frames_ >= badFrame_ && out.size() > 10) out[10].x = std::nanf("");
  }
  std::optional<FrameSample> takeSample(bool wait) override {
    std::optional<FrameSample> s = inner_.takeSample(wait);
    if (s && s->frame >= badFrame_) s->accuracy.nanCount = 1;
    return s;
  }

 private:
  long badFrame_;
  long frames_ = 0;
};

// A CPU solver whose frames wait for the test to let them through: a simulation as slow as
// the test likes.
class GatedSolver final : public WrappedSolver {
 public:
  struct Gate {
    std::mutex m;
    std::condition_variable cv;
    long allowed = 0;  // frames that may run
    std::atomic<long> started{0};
  };
  explicit GatedSolver(std::shared_ptr<Gate> gate) : gate_(std::move(gate)) {}
  std::string_view name() const override { return "gated"; }
  using Solver::stepFrame;
  void stepFrame(const FramePath& path) override {
    const long n = ++gate_->started;
    std::unique_lock lock(gate_->m);
    gate_->cv.wait(lock, [&] { return gate_->allowed >= n; });
    inner_.stepFrame(path);
  }

 private:
  std::shared_ptr<Gate> gate_;
};

// Lets `frames` more frames of the gated solver run.
inline void allow(GatedSolver::Gate& gate, long frames) {
  {
    std::lock_guard lock(gate.m);
    gate.allowed += frames;
  }
  gate.cv.notify_all();
}

}  // namespace csm::test
