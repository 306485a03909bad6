// Cost against error for every method and setting: one row of methods.csv per setting.
#include <cmath>
#include <cstdio>
#include <mutex>

#include <glm/geometric.hpp>

#include "tools/bench/bench.h"
#include "tools/bench/csv.h"
#include "sim/core/pose.h"
#include "sim/solver/accuracy.h"

namespace csm::bench {
namespace {

struct MethodResult {
  bool diverged = false;  // NaN or stretch beyond 100% in the main scene
  double maxStrain = NAN, meanStrain = NAN;
  uint64_t headPenetrations = 0;
  double hairPairs = NAN;  // segment pairs closer than the hair radius, mean over sample times
  PositionError timeStep{NAN, NAN};
  double resolutionRmsMm = NAN;
  double sag[3] = {NAN, NAN, NAN};  // 8, 16, 32 particles
  double pendulumErrorPct = NAN;
  double msPerSimSecond = NAN;
  int substepsUsed = 0;  // steps per frame the solver took (calibrated: at least the setting's)
};

constexpr int kResolutions[3] = {8, 16, 32};

void mainSceneAccuracy(const Setting& s, const Scene& base, const std::vector<double>& times,
                       MethodResult& r) {
  Scene scene = base;
  s.apply(scene.config);
  Scene fine = scene;
  fine.config.sim.substeps *= 16;
  SceneRunner run(s.maker(), scene), refRun(s.maker(), fine);
  r.substepsUsed = s.isCsm() ? run.diagnostics().stiffness().plan.substeps : s.substeps;
  const std::vector<double> rest = restLengths(scene.groom);
  ErrorAccumulator err(scene.groom, scene.config.sim.pinned);
  std::vector<glm::vec4> x, v, xr;
  double strainSum = 0.0, pairs = 0.0;
  long frames = 0;
  r.maxStrain = 0.0;
  for (double t : times) {
    while (run.time() < t - 0.5 * scene.config.sim.dt) {
      run.frame();
      run.readPositions(x);
      run.readVelocities(v);
      const auto spheres =
          worldSpheres(scene.config.head.spheres, headPose(scene.config.head, run.time()));
      const Accuracy a = measureAccuracy(x, v, scene.groom, rest, spheres, scene.config.sim.pinned);
      if (a.nanCount > 0 || a.maxStrain > 1.0) {
        r.diverged = true;
        r.maxStrain = a.nanCount ? INFINITY : a.maxStrain;
        return;
      }
      r.maxStrain = std::max(r.maxStrain, a.maxStrain);
      r.headPenetrations = std::max(r.headPenetrations, a.headPenetrations);
      strainSum += a.meanStrain;
      ++frames;
    }
    pairs += double(closeSegmentPairs(x, scene.groom, scene.config.collision.radius));
    refRun.runTo(t);
    refRun.readPositions(xr);
    err.add(x, xr);
  }
  r.meanStrain = strainSum / std::max(1L, frames);
  r.hairPairs = pairs / double(times.size());
  r.timeStep = err.result();
}

// The swing: tip paths of the 8- and 16-particle strands against the 32-particle one over the
// first `swing` seconds after release. The sag: each strand settled with strong damping.
void resolutionAccuracy(const Setting& s, double swing, double settle, MethodResult& r) {
  CantileverRun runs[3];
  for (int k = 0; k < 3; ++k) {
    runs[k] = runCantilever(s, kResolutions[k], -1, swing);
    r.sag[k] = runCantilever(s, kResolutions[k], -1, settle, kSettleDamping, kSagGravity).sagMm;
  }
  if (!runs[0].finite || !runs[1].finite || !runs[2].finite) return;
  double sum = 0.0;
  size_t count = 0;
  for (int k = 0; k < 2; ++k)
    for (size_t f = 0; f < runs[2].tip.size(); ++f) {
      const glm::dvec3 d = runs[k].tip[f] - runs[2].tip[f];
      sum += glm::dot(d, d);
      ++count;
    }
  r.resolutionRmsMm = count ? 1000.0 * std::sqrt(sum / double(count)) : NAN;
}

void pendulumAccuracy(const Setting& s, MethodResult& r) {
  Scene scene = pendulumScene(16, 0.25, 0.1);
  s.apply(scene.config);
  // The rigid strand: one region spanning it, a free pivot, nothing else acting. The same in
  // both stiffness models (alpha = 1 on a rigid strand), so measured with the paper's.
  scene.config.sim.stiffnessModel = StiffnessModel::Paper;
  scene.config.sim.stiffnessWindow = 16;
  scene.config.sim.pinned = 1;
  scene.config.collision.mode = CollisionMode::Off;
  const PendulumResult p = measurePendulum(s.maker(), scene, 4.0);
  if (p.finite && p.crossings >= 2) r.pendulumErrorPct = 100.0 * p.relativeError;
}

}  // namespace

void runMethods(const Options& o) {
  const std::vector<Setting> settings = methodSettings(o);
  const Scene scene = mainScene(o);
  const std::vector<double> times =
      o.quick ? std::vector<double>{0.25, 0.5} : std::vector<double>{0.25, 0.5, 0.75, 1.0};
  const double swingSeconds = 1.0, settleSeconds = o.quick ? 1.5 : 2.0;
  std::vector<MethodResult> results(settings.size());
  std::fprintf(stderr, "methods: %zu settings on %zu strands, %zu particles\n", settings.size(),
               scene.groom.strandCount(), scene.groom.pointCount());
  std::mutex log;
  auto accuracy = [&](int i) {
    const Setting& s = settings[i];
    MethodResult& r = results[i];
    mainSceneAccuracy(s, scene, times, r);
    resolutionAccuracy(s, swingSeconds, settleSeconds, r);
    pendulumAccuracy(s, r);
    std::lock_guard<std::mutex> lock(log);
    std::fprintf(stderr,
                 "  %-26s %-12s stretch %.4f  dt-error %.3f mm  res %.2f mm  pendulum %+.2f%%%s\n",
                 s.family.c_str(), s.label.c_str(), r.maxStrain, r.timeStep.rmsMm,
                 r.resolutionRmsMm, r.pendulumErrorPct, r.diverged ? "  DIVERGED" : "");
  };
  // GPU settings need the GL context, which is current on this thread only.
  std::vector<int> cpuJobs, gpuJobs;
  for (int i = 0; i < int(settings.size()); ++i)
    (settings[i].solver == "gpu" ? gpuJobs : cpuJobs).push_back(i);
  parallelFor(int(cpuJobs.size()), o.threads, [&](int k) { accuracy(cpuJobs[k]); });
  for (int i : gpuJobs) accuracy(i);

  // Timings alone, one setting at a time.
  const int frames = o.quick ? 15 : 30;
  for (size_t i = 0; i < settings.size(); ++i) {
    results[i].msPerSimSecond = msPerSimulatedSecond(settings[i], scene, frames);
    std::fprintf(stderr, "  %-26s %-12s %9.1f ms per simulated second\n",
                 settings[i].family.c_str(), settings[i].label.c_str(), results[i].msPerSimSecond);
  }

  Csv csv({"family",
           "label",
           "solver",
           "model",
           "window_length_m",
           "substeps",
           "substeps_used",
           "window",
           "strain_limiting",
           "dftl",
           "collision",
           "stretch_stiffness_n",
           "iterations",
           "strands",
           "particles",
           "ms_per_sim_s",
           "diverged",
           "max_strain",
           "mean_strain",
           "head_penetrations",
           "hair_pairs_closer_than_r",
           "timestep_rms_mm",
           "timestep_max_mm",
           "resolution_rms_mm",
           "sag8_mm",
           "sag16_mm",
           "sag32_mm",
           "pendulum_error_pct"});
  for (size_t i = 0; i < settings.size(); ++i) {
    const Setting& s = settings[i];
    const MethodResult& r = results[i];
    const bool csmLike = s.isCsm();
    const bool calibrated = csmLike && s.model == StiffnessModel::Calibrated;
    // Calibrated settings are labelled with the steps they took.
    char label[64];
    std::snprintf(label, sizeof label, "%gcm s%d", 100.0 * s.windowLength, r.substepsUsed);
    csv.add(s.family).add(calibrated ? std::string(label) : s.label).add(s.solver);
    csv.add(csmLike ? (calibrated ? "calibrated" : "paper") : "");
    csv.add(calibrated ? double(s.windowLength) : NAN).add(s.substeps).add(r.substepsUsed);
    csv.add(csmLike ? double(s.window) : NAN).add(s.strainLimiting).add(double(s.dftl));
    csv.add(collisionModeName(s.collision));
    csv.add(s.solver.rfind("ms-", 0) == 0 ? s.params.stretchStiffness : NAN);
    csv.add(s.solver == "pbd" ? double(s.params.iterations) : NAN);
    csv.add(scene.groom.strandCount()).add(scene.groom.pointCount());
    csv.add(r.msPerSimSecond).add(r.diverged).add(r.maxStrain).add(r.meanStrain);
    csv.add(r.diverged ? NAN : double(r.headPenetrations)).add(r.hairPairs);
    csv.add(r.timeStep.rmsMm).add(r.timeStep.maxMm).add(r.resolutionRmsMm);
    csv.add(r.sag[0]).add(r.sag[1]).add(r.sag[2]).add(r.pendulumErrorPct);
    csv.endRow();
  }
  csv.write(o.out + "/methods.csv");
}

}  // namespace csm::bench
