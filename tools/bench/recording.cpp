// The timeline's price (sim/run/frame_recording.h, the viewer's Timeline panel): per frame, what
// recording costs beside the step it records (the positions read back, a keyframe's whole state
// every 30 frames), the memory a frame and a keyframe take, and how long a resume takes from the
// frame farthest from its keyframe (29 frames stepped again).
#include <chrono>
#include <cstdio>
#include <memory>

#include "sim/run/make_solver.h"
#include "sim/run/frame_recording.h"
#include "sim/run/simulation.h"
#include "tools/bench/bench.h"
#include "tools/bench/csv.h"

namespace csm::bench {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace

void runRecording(const Options& o) {
  Csv csv({"solver", "strands", "particles", "frames", "step_ms", "record_ms", "record_key_ms",
           "frame_bytes", "key_bytes", "resume_ms", "resume_mismatch_m"});
  std::vector<std::string> solvers = {"cpu"};
  if (o.gpu) solvers.push_back("gpu");
  const std::vector<int> counts = o.quick ? std::vector<int>{500} : std::vector<int>{500, 3000};
  const int frames = o.quick ? 31 : 61;  // keyframes at 0, 30, 60
  for (const std::string& name : solvers)
    for (int strands : counts) {
      std::string error;
      std::unique_ptr<Simulation> made = makeSimulation(name, &error);
      if (!made) continue;
      Simulation& sim = *made;
      if (!sim.load(presetConfig(o, "default", strands), o.source + "/presets", &error)) {
        std::fprintf(stderr, "recording: %s\n", error.c_str());
        continue;
      }
      FrameRecording recorder;
      double stepMs = 0.0, recordMs = 0.0, keyMs = 0.0;
      int keys = 0;
      for (int f = 0; f < frames; ++f) {
        auto t0 = Clock::now();
        sim.stepFrame();
        sim.diagnostics().finish();
        stepMs += msSince(t0);
        const size_t before = recorder.keyframeCount();
        t0 = Clock::now();
        recorder.record(sim);
        const double ms = msSince(t0);
        if (recorder.keyframeCount() > before) {
          keyMs += ms;
          ++keys;
        } else {
          recordMs += ms;
        }
      }
      const int plain = frames - keys;
      const size_t frameBytes = sim.counts().particles * sizeof(glm::vec3);
      SimulationState state;
      sim.save(state);
      // The frame farthest from its keyframe: 29 frames stepped again.
      const long target = recorder.firstFrame() + 29;
      double mismatch = -1.0;
      auto t0 = Clock::now();
      const bool ok = recorder.resume(sim, target, &error, &mismatch);
      sim.diagnostics().finish();
      const double resumeMs = msSince(t0);
      if (!ok) std::fprintf(stderr, "recording: %s\n", error.c_str());
      csv.add(name).add(strands).add(long(sim.counts().particles)).add(frames);
      csv.add(stepMs / frames).add(recordMs / plain).add(keyMs / std::max(1, keys));
      csv.add(long(frameBytes)).add(long(state.bytes())).add(resumeMs).add(mismatch);
      csv.endRow();
      std::fprintf(stderr,
                   "recording: %s, %d strands: step %.2f ms, record %.3f ms a frame, %.2f ms a "
                   "keyframe; %zu B a frame, %zu B a keyframe; resume 29 frames past a "
                   "keyframe %.1f ms (mismatch %g m)\n",
                   name.c_str(), strands, stepMs / frames, recordMs / plain,
                   keyMs / std::max(1, keys), frameBytes, state.bytes(), resumeMs, mismatch);
    }
  csv.write(o.out + "/recording.csv");
}

}  // namespace csm::bench
