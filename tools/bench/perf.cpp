// Cost alone: region sums by prefix differences against direct sums, and ms per step against
// strand count for the CPU reference and the GPU solver.
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "tools/bench/bench.h"
#include "tools/bench/csv.h"

namespace csm::bench {
namespace {

// The fastest frame's ms over at least `minFrames` frames and `minMs` ms, after one warm-up
// frame: the scene does the same work every frame, the machine is shared, and other work
// only ever adds time. Each frame is timed to completion (SceneRunner::timedFrame).
double msPerFrame(SceneRunner& run, int minFrames, double minMs, int maxFrames) {
  run.timedFrame();
  std::vector<double> frames;
  double total = 0.0;
  while (int(frames.size()) < maxFrames && (int(frames.size()) < minFrames || total < minMs)) {
    frames.push_back(run.timedFrame());
    total += frames.back();
  }
  return *std::min_element(frames.begin(), frames.end());
}

}  // namespace

void runRegionSums(const Options& o) {
  Csv csv({"window", "sums", "strands", "particles", "ms_per_step"});
  const Scene base = cantileverScene(32, 0.25, o.quick ? 100 : 200);
  std::fprintf(stderr, "region sums: %zu strands x 32 particles\n", base.groom.strandCount());
  for (int w :
       o.quick ? std::vector<int>{1, 2, 4, 8, 16} : std::vector<int>{1, 2, 3, 4, 6, 8, 12, 16}) {
    for (const char* sums : {"csm", "csm-direct"}) {
      Setting s;
      s.solver = sums;
      s.window = w;
      s.substeps = 1;
      s.collision = CollisionMode::Off;
      Scene scene = base;
      const int pinned = scene.config.sim.pinned;
      s.apply(scene.config);
      scene.config.sim.pinned = pinned;
      SceneRunner run(s.maker(), scene);
      const double ms = msPerFrame(run, o.quick ? 5 : 10, 200.0, 200);
      csv.add(w).add(std::string(sums) == "csm" ? "prefix" : "direct");
      csv.add(scene.groom.strandCount()).add(scene.groom.pointCount()).add(ms);
      csv.endRow();
      std::fprintf(stderr, "  w=%2d %-10s %7.2f ms/step\n", w, sums, ms);
    }
  }
  csv.write(o.out + "/region_sums.csv");
}

void runScaling(const Options& o) {
  Csv csv({"series", "device", "strands", "particles", "ms_per_step"});
  const std::vector<int> counts =
      o.quick ? std::vector<int>{1000, 2000, 5000, 10000}
              : std::vector<int>{1000, 2000, 5000, 10000, 20000, 50000, 100000};
  struct Series {
    std::string name, device, solver;
    CollisionMode mode;
    double budgetMs;  // stop growing once a step costs more than this
  };
  std::vector<Series> series = {
      {"CPU reference, head collisions", "cpu", "csm", CollisionMode::Head,
       o.quick ? 400.0 : 1500.0},
      {"CPU reference, hair-hair collisions", "cpu", "csm", CollisionMode::Strands,
       o.quick ? 400.0 : 1000.0},
  };
  if (o.gpu) {
    series.push_back({"GPU, head collisions", "gpu", "gpu", CollisionMode::Head, 2500.0});
    series.push_back({"GPU, hair-hair collisions", "gpu", "gpu", CollisionMode::Strands, 2500.0});
  }
  for (const Series& se : series) {
    for (int n : counts) {
      Scene scene = presetScene(o, "default", n);
      // One step a frame whatever the stiffness asks (a step costs the same at any alpha).
      scene.config.sim.substeps = 1;
      scene.config.sim.maxSubsteps = 1;
      scene.config.collision.mode = se.mode;
      Setting s;
      s.solver = se.solver;
      SceneRunner run(s.maker(), scene);
      if (!run.ok()) {
        std::fprintf(stderr, "  %s: no solver\n", se.name.c_str());
        break;
      }
      const double ms = msPerFrame(run, 3, 300.0, 50);
      csv.add(se.name).add(se.device).add(n).add(scene.groom.pointCount()).add(ms);
      csv.endRow();
      std::fprintf(stderr, "  %-38s %6d strands %8zu particles %9.2f ms/step\n", se.name.c_str(), n,
                   scene.groom.pointCount(), ms);
      if (ms > se.budgetMs) break;
    }
  }
  csv.write(o.out + "/scaling.csv");
}

}  // namespace csm::bench
