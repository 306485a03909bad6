// One frame, the same for the window's simulation thread, headless runs and the benchmarks:
// step, sample the measures without waiting (the solver's fenced ring, read a few frames
// late), and stop on NaN. Nothing here reads the hair's state back: a sample is a few numbers
// per work group (Solver::requestSample).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "sim/run/simulation.h"

namespace csm {

struct DriverOptions {
  // Frames between samples; 1 samples every frame (metrics), more only watches for NaN, 0
  // takes none (timing runs that check their results themselves).
  int sampleEvery = 10;
  // Take each frame's sample before the next frame (waiting for it): for runs that write
  // frames out, so that none is written before its NaN check.
  bool waitForSamples = false;
  // Wait for each frame's GPU work to end before timing it (glFinish): honest wall times for
  // the metrics, a stall otherwise.
  bool timeToCompletion = false;
};

class FrameDriver {
 public:
  // Steps `sim` (the program).
  FrameDriver(Simulation& sim, const DriverOptions& options);
  // Steps whatever `stepFrame` steps on `solver` (a benchmark's scene runner); it returns the
  // number of the frame it finished.
  FrameDriver(Solver& solver, std::function<long()> stepFrame, const DriverOptions& options)
      : solver_(solver), stepFrame_(std::move(stepFrame)), options_(options) {}

  // One frame, unless stopped on NaN. Takes whatever samples are ready; with waitForSamples,
  // this frame's.
  void step();
  // Takes every sample still in flight, waiting for them (the end of a run).
  void drain();
  // After the simulation was reset or regrown: samples in flight are of another state.
  void restart();

  // Samples taken since the last call, oldest first.
  std::vector<FrameSample> takeSamples();
  const std::optional<FrameSample>& latestSample() const { return latest_; }

  // The NaN policy: a sample that counts non-finite particles stops the driver.
  bool stopped() const { return nanFrame_ >= 0; }
  long nanFrame() const { return nanFrame_; }
  uint64_t nanParticles() const { return nanParticles_; }
  // Clears a stop (after the hair was reset).
  void resume();

  double lastStepMs() const { return lastStepMs_; }

 private:
  void take(bool wait);
  void accept(const FrameSample& sample);

  Solver& solver_;
  std::function<long()> stepFrame_;
  DriverOptions options_;
  std::vector<FrameSample> taken_;
  std::optional<FrameSample> latest_;
  long nanFrame_ = -1;
  uint64_t nanParticles_ = 0;
  double lastStepMs_ = 0.0;
};

}  // namespace csm
