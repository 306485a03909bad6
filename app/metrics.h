// Per-frame timings and the frames' samples (their accuracy), written as the --metrics JSON.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/core/config.h"
#include "sim/groom/scene_groom.h"
#include "sim/core/results.h"

namespace csm {

struct SceneSetup;  // app/scene_setup.h
struct SimFrame;    // app/sim_frame.h

class MetricsLog {
 public:
  // A simulated frame: its wall time and the solver's stage times.
  void addFrame(double simMs, const std::vector<StageTime>& stages);
  // A frame's measures, when its sample comes (a few frames later).
  void addSample(const FrameSample& sample);
  void addRender(double renderMs, const std::vector<StageTime>& stages);
  // The window: wall time between UI frames.
  void addUiFrame(double ms);

  long frames() const { return long(simMs_.size()); }
  long samples() const { return samples_; }
  double simMean() const;
  double simP95() const;
  const Accuracy& worst() const { return worst_; }
  uint64_t nanCount() const { return worst_.nanCount; }

  // `meta` holds the scene's description (strands, particles, solver, device...); the
  // recorder adds "frames", "ms" and "accuracy".
  nlohmann::json toJson(nlohmann::json meta) const;
  bool write(const std::string& path, const nlohmann::json& meta, std::string* error) const;

 private:
  std::vector<double> simMs_, renderMs_, uiMs_;
  long samples_ = 0;
  std::map<std::string, double> stageSum_, renderStageSum_;
  Accuracy worst_;  // max strain, max speed, max NaN count, summed head penetrations
  double meanStrainSum_ = 0.0;
  uint64_t contactsLast_ = 0, penetrationsLast_ = 0, penetrationsMax_ = 0;
  // Strand contacts summed over the samples (ContactStats::add); pairs closer than r in the
  // list of the first frame (built from the rest state).
  ContactStats contactSum_;
  long contactSamples_ = 0;
  int64_t restPenetrations_ = -1;
};

// What ran, for the metrics' header: the same fields from headless runs and the window.
struct RunDescription {
  std::string preset, source;
  Config config;
  StiffnessInfo stiffness;
  MemoryUse memory;                        // the solver's buffers by kind
  std::size_t strands = 0, particles = 0;  // simulated
  std::size_t groomStrands = 0;            // drawn: followers included, children not
  std::string solver;
  std::string solverVariant;  // the GPU solver's kernel path (SolverDiagnostics::variant)
  GroomReport groom;
  // Where the solver ran: the GL renderer string for the GPU solver (e.g. "llvmpipe (LLVM
  // 15.0.6, 256 bits)" or "NVIDIA H100 80GB HBM3/PCIe/SSE2"), "cpu" otherwise.
  std::string device;
};
// The one place a RunDescription is filled, for headless runs and the window alike: `scene` as
// set up, the running scene's figures as a SimFrame carries them (the window's latest frame; a
// headless run takes them from its Simulation with takeFigures, app/sim_frame.h), and the
// device the solver ran on.
RunDescription runDescription(const SceneSetup& scene, const SimFrame& figures,
                              const std::string& device);
nlohmann::json describeRun(const RunDescription& run);
// The process's peak resident memory so far (bytes; Linux's VmHWM, 0 where it cannot be read).
uint64_t peakResidentBytes();
// "memory" of the metrics: the peak resident size, the solver's buffers by kind, their total and
// bytes per simulated particle.
nlohmann::json describeMemory(const MemoryUse& memory, std::size_t particles);

}  // namespace csm
