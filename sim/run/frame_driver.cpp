#include "sim/run/frame_driver.h"

namespace csm {

using Clock = std::chrono::steady_clock;

FrameDriver::FrameDriver(Simulation& sim, const DriverOptions& options)
    : FrameDriver(
          sim.solver(),
          [&sim] {
            sim.stepFrame();
            return sim.frame();
          },
          options) {}

void FrameDriver::step() {
  if (stopped()) return;
  // Timed to completion, the frame's time starts when the GPU has done what came before it
  // (the last sample's measures among them).
  if (options_.timeToCompletion) solver_.finish();
  const auto t0 = Clock::now();
  const long frame = stepFrame_();
  if (options_.timeToCompletion) solver_.finish();
  lastStepMs_ = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  const bool due = options_.waitForSamples || options_.sampleEvery == 1 ||
                   (options_.sampleEvery > 1 && frame % options_.sampleEvery == 0);
  if (due) solver_.requestSample(frame);
  take(options_.waitForSamples);
}

void FrameDriver::take(bool wait) {
  while (std::optional<FrameSample> s = solver_.takeSample(wait)) accept(*s);
}

void FrameDriver::accept(const FrameSample& sample) {
  latest_ = sample;
  taken_.push_back(sample);
  if (sample.accuracy.nanCount > 0 && !stopped()) {
    nanFrame_ = sample.frame;
    nanParticles_ = sample.accuracy.nanCount;
  }
}

void FrameDriver::drain() {
  take(true);
}

void FrameDriver::restart() {
  solver_.dropSamples();
  latest_.reset();
  resume();
}

void FrameDriver::resume() {
  nanFrame_ = -1;
  nanParticles_ = 0;
}

std::vector<FrameSample> FrameDriver::takeSamples() {
  std::vector<FrameSample> out;
  out.swap(taken_);
  return out;
}

}  // namespace csm
