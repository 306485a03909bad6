// The torture map and the soak (docs/RELIABILITY.md): sim/verify/torture.h's cells on the CPU
// solver (and the GPU one with --gpu), and a long run of a small scene.
#include <algorithm>
#include <cstdio>

#include "sim/run/make_solver.h"
#include "sim/groom/hairstyle.h"
#include "sim/verify/torture.h"
#include "sim/head/head_model.h"
#include "tools/bench/bench.h"
#include "tools/bench/csv.h"
#include "sim/verify/soak.h"

namespace csm::bench {

namespace {

SolverMaker factory(const std::string& solver) {
  return solverMaker(solver == "gpu" ? "gpu" : "cpu");
}

}  // namespace

void runTortureMap(const Options& o) {
  const int strands = o.quick ? 60 : 150;
  const double duration = o.quick ? 1.0 : 2.0;
  const Config base = presetConfig(o, "default", strands);
  const TortureCriteria criteria;
  struct Run {
    std::string solver;
    TortureCell cell;
    TortureResult result;
  };
  std::vector<Run> runs;
  for (const TortureCell& c : tortureCells(base, TortureScope::Full, duration))
    runs.push_back({"cpu", c, {}});
  if (o.gpu)
    for (const TortureCell& c : tortureCells(base, TortureScope::Full, duration))
      runs.push_back({"gpu", c, {}});
  const int cpuRuns =
      int(std::count_if(runs.begin(), runs.end(), [](const Run& r) { return r.solver == "cpu"; }));
  std::fprintf(stderr, "torture: %d CPU and %d GPU cells of %.0f s, %d strands\n", cpuRuns,
               int(runs.size()) - cpuRuns, duration, strands);
  auto report = [&](const Run& r) {
    std::fprintf(stderr, "  %-4s %-48s %s%s\n", r.solver.c_str(), r.cell.name().c_str(),
                 r.result.pass() ? "pass" : "FAIL: ", r.result.failures().c_str());
  };
  parallelFor(cpuRuns, o.threads, [&](int i) {
    runs[i].result = runTorture(factory("cpu"), runs[i].cell, criteria);
    report(runs[i]);
  });
  // The GPU solver needs the context, current on this thread.
  for (int i = cpuRuns; i < int(runs.size()); ++i) {
    runs[i].result = runTorture(factory("gpu"), runs[i].cell, criteria);
    report(runs[i]);
  }

  Csv csv({"solver",       "axis",
           "value",        "mode",
           "strands",      "dt",
           "frames",       "steps_per_frame",
           "finite",       "nonfinite_frame",
           "max_strain",   "strain_limit",
           "stretch_ok",   "deepest_mm",
           "max_inside",   "inside_frames",
           "head_checked", "head_ok",
           "peak_speed",   "peak_speed_frame",
           "rigid_speed",  "wind_speed",
           "fall_speed",   "speed_bound",
           "speed_ok",     "pass",
           "failures",     "wall_s"});
  int failed = 0;
  for (const Run& r : runs) {
    const TortureResult& x = r.result;
    csv.add(r.solver).add(r.cell.axis).add(r.cell.value);
    csv.add(collisionModeName(r.cell.config.collision.mode)).add(strands);
    csv.add(double(r.cell.config.sim.dt)).add(x.frames).add(x.stepsPerFrame);
    csv.add(x.finite).add(x.nonFiniteFrame).add(x.maxStrain).add(x.strainLimit);
    csv.add(x.stretchOk).add(x.deepestMm).add(x.maxInside).add(x.insideFrames);
    csv.add(x.headChecked).add(x.headOk).add(x.peakSpeed).add(x.peakSpeedFrame);
    csv.add(x.rigidSpeed).add(x.windSpeed).add(x.fallSpeed).add(x.speedBound);
    csv.add(x.speedOk).add(x.pass()).add(x.failures()).add(x.wallSeconds);
    csv.endRow();
    failed += !x.pass();
  }
  csv.write(o.out + "/torture.csv");
  std::fprintf(stderr,
               "  %d of %zu cells failed (criteria: stretch <= limit + %.3f, head <= "
               "%.1f mm, speed <= %.0f x (head + wind) + free fall)\n",
               failed, runs.size(), criteria.strainTolerance, criteria.penetrationMm,
               criteria.speedFactor);
}

void runSoakSection(const Options& o) {
  struct Plan {
    std::string solver;
    SoakOptions options;
  };
  std::vector<Plan> plans;
  {
    SoakOptions s;
    s.frames = o.quick ? 10000 : 100000;
    s.movingFrames = s.frames / 5;  // 1.5 Hz at 1/60 s: a whole period every 40 frames
    plans.push_back({"cpu", s});
  }
  if (o.gpu) {
    SoakOptions s;
    s.frames = o.quick ? 1000 : 100000;
    s.movingFrames = s.frames / 5;
    plans.push_back({"gpu", s});
  }
  const int strands = 64;
  const Config scene = soakScene(presetConfig(o, "default", strands), strands);
  Csv samples({"solver", "frame", "rss_kb"});
  Csv summary({"solver",
               "mode",
               "strands",
               "particles",
               "frames",
               "moving_frames",
               "finite",
               "nonfinite_frame",
               "max_strain",
               "max_strain_frame",
               "strained_frames",
               "wall_s",
               "frames_per_s",
               "rss_start_kb",
               "rss_warm_kb",
               "rss_end_kb",
               "rss_max_kb",
               "hwm_end_kb",
               "at_stop_rms_mm",
               "at_stop_max_mm",
               "to_rest_rms_mm",
               "to_rest_max_mm",
               "strand_median_mm",
               "strand_p90_mm",
               "strand_max_mm",
               "still_drift_rms_mm",
               "still_drift_max_mm",
               "rest_run_wall_s"});
  for (const Plan& p : plans) {
    std::fprintf(stderr, "soak: %s, %ld frames (%ld moving), %d strands\n", p.solver.c_str(),
                 p.options.frames, p.options.movingFrames, strands);
    const SoakResult r =
        runSoak(factory(p.solver), scene, p.options, [&](long frame, const SoakResult& s) {
          if (frame % (p.options.frames / 10) == 0)
            std::fprintf(stderr, "  frame %ld: RSS %ld kB\n", frame, s.rss.back().second);
        });
    for (const auto& [frame, kb] : r.rss) samples.add(p.solver).add(frame).add(kb).endRow();
    summary.add(p.solver).add(collisionModeName(scene.collision.mode)).add(strands);
    summary.add(long(growHairstyle(scene, *HeadModel::require(scene)).pointCount()));
    summary.add(r.frames).add(p.options.movingFrames).add(r.finite).add(r.nonFiniteFrame);
    summary.add(r.maxStrain).add(r.maxStrainFrame).add(r.strainedFrames);
    summary.add(r.wallSeconds).add(r.framesPerSecond);
    summary.add(r.rssStartKb).add(r.rssWarmKb).add(r.rssEndKb).add(r.rssMaxKb).add(r.hwmEndKb);
    summary.add(r.atStop.rmsMm).add(r.atStop.maxMm).add(r.toRest.rmsMm).add(r.toRest.maxMm);
    summary.add(r.strandsToRest.quantile(0.5)).add(r.strandsToRest.quantile(0.9));
    summary.add(r.strandsToRest.quantile(1.0));
    summary.add(r.stillDrift.rmsMm).add(r.stillDrift.maxMm);
    summary.add(r.restWallSeconds);
    summary.endRow();
    std::fprintf(stderr,
                 "  %s: %s, largest stretch %.4f (frame %ld; %ld frames past the limit), "
                 "%.0f frames/s, RSS %ld -> %ld kB (after warm-up %ld, max %ld), "
                 "from rest %.3f mm RMS %.3f max a second after the stop, at the end "
                 "%.4f RMS %.4f max, per strand %.2f mm median %.2f 90th percentile %.2f "
                 "max; drift over the last half of the still part %.5f RMS %.5f max\n",
                 p.solver.c_str(), r.finite ? "finite" : "NON-FINITE", r.maxStrain,
                 r.maxStrainFrame, r.strainedFrames, r.framesPerSecond, r.rssStartKb, r.rssEndKb,
                 r.rssWarmKb, r.rssMaxKb, r.atStop.rmsMm, r.atStop.maxMm, r.toRest.rmsMm,
                 r.toRest.maxMm, r.strandsToRest.quantile(0.5), r.strandsToRest.quantile(0.9),
                 r.strandsToRest.quantile(1.0), r.stillDrift.rmsMm, r.stillDrift.maxMm);
  }
  samples.write(o.out + "/soak_rss.csv");
  summary.write(o.out + "/soak.csv");
}

}  // namespace csm::bench
