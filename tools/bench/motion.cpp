// How far hair moves between candidate searches, in the head's frame (a rigid move of the head
// changes no distance between strands): each frame, every particle's move since the last frame
// (median, 99th percentile, most), the move of near neighbours (other particles within 3 mm)
// relative to each other, and how many searches a list kept over several frames would need if
// it may miss nothing: a list made with `skin` more than the frame's candidate distance holds
// every pair a fresh search would find while no particle has moved more than skin / 2 since
// (the Verlet list's rule). The lever "lists that live several frames" of
// docs/BENCHMARKS_HISTORY.md is measured here: --only motion.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "sim/run/make_solver.h"
#include "sim/run/simulation.h"
#include "tools/bench/bench.h"
#include "tools/bench/csv.h"

namespace csm::bench {
namespace {

using Frame = std::vector<glm::dvec3>;

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(q * double(v.size())))];
}

// The largest move of particle i relative to the particles within `reach` of it at `before`,
// for every `stride`-th particle.
std::vector<double> relativeMoves(const Frame& before, const Frame& after, double reach,
                                  size_t stride) {
  auto key = [&](const glm::dvec3& p) {
    const glm::dvec3 c = glm::floor(p / reach);
    return (uint64_t(int64_t(c.x) & 0x1fffff) << 42) | (uint64_t(int64_t(c.y) & 0x1fffff) << 21) |
           uint64_t(int64_t(c.z) & 0x1fffff);
  };
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells;
  for (size_t i = 0; i < before.size(); ++i) cells[key(before[i])].push_back(uint32_t(i));
  std::vector<double> out;
  for (size_t i = 0; i < before.size(); i += stride) {
    const glm::dvec3 move = after[i] - before[i];
    double most = 0.0;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = cells.find(key(before[i] + reach * glm::dvec3(dx, dy, dz)));
          if (it == cells.end()) continue;
          for (uint32_t j : it->second)
            if (glm::length(before[j] - before[i]) < reach)
              most = std::max(most, glm::length(move - (after[j] - before[j])));
        }
    out.push_back(most);
  }
  return out;
}

}  // namespace

void runMotion(const Options& o) {
  Csv csv({"preset", "solver", "frame", "move_p50_mm", "move_p99_mm", "move_max_mm",
           "relative_p50_mm", "relative_p99_mm", "relative_max_mm"});
  Csv searches({"preset", "solver", "frames", "skin_mm", "searches"});
  const int frames = o.quick ? 20 : 60;
  const char* solverName = o.gpu ? "gpu" : "cpu";
  const std::pair<const char*, int> scenes[] = {{"default", 3000}, {"paper_fig1_straight", 10000}};
  for (const auto& [preset, strands] : scenes) {
    Config c = presetConfig(o, preset, strands);
    c.collision.mode = CollisionMode::VolumeStrands;
    std::string error;
    std::unique_ptr<Simulation> made = makeSimulation(solverName, &error);
    if (!made) return;
    Simulation& sim = *made;
    if (!sim.load(c, o.source + "/presets", &error)) {
      std::fprintf(stderr, "motion: %s: %s\n", preset, error.c_str());
      return;
    }
    std::vector<Frame> seen;
    std::vector<glm::vec4> x;
    for (int f = 0; f <= frames; ++f) {
      if (f > 0) sim.stepFrame();
      sim.readPositions(x);
      const Pose toHead = inverse(sim.headPose());
      Frame h(x.size());
      for (size_t i = 0; i < x.size(); ++i) h[i] = toHead.apply(glm::dvec3(glm::vec3(x[i])));
      seen.push_back(std::move(h));
    }
    const size_t n = seen[0].size();
    for (int f = 1; f <= frames; ++f) {
      std::vector<double> move(n);
      for (size_t i = 0; i < n; ++i) move[i] = glm::length(seen[f][i] - seen[f - 1][i]);
      const std::vector<double> rel = relativeMoves(seen[f - 1], seen[f], 0.003, 7);
      csv.add(preset).add(solverName).add(f);
      for (double q : {0.5, 0.99, 1.0}) csv.add(1e3 * quantile(move, q));
      for (double q : {0.5, 0.99, 1.0}) csv.add(1e3 * quantile(rel, q));
      csv.endRow();
      if (f % 10 == 0)
        std::fprintf(stderr,
                     "motion %s frame %d: move p50 %.2f p99 %.2f max %.2f mm; relative to "
                     "neighbours within 3 mm p50 %.2f p99 %.2f max %.2f mm\n",
                     preset, f, 1e3 * quantile(move, 0.5), 1e3 * quantile(move, 0.99),
                     1e3 * quantile(move, 1.0), 1e3 * quantile(rel, 0.5), 1e3 * quantile(rel, 0.99),
                     1e3 * quantile(rel, 1.0));
    }
    for (double skin : {1e-3, 2e-3, 4e-3, 8e-3, 16e-3}) {
      int count = 1, made = 0;
      for (int f = 1; f <= frames; ++f) {
        double most = 0.0;
        for (size_t i = 0; i < n; ++i)
          most = std::max(most, glm::length(seen[f][i] - seen[made][i]));
        if (2.0 * most > skin) {
          ++count;
          made = f;
        }
      }
      searches.add(preset).add(solverName).add(frames).add(1e3 * skin).add(count);
      searches.endRow();
      std::fprintf(stderr, "motion %s: a list kept with a %.0f mm skin: %d searches in %d frames\n",
                   preset, 1e3 * skin, count, frames);
    }
  }
  csv.write(o.out + "/motion.csv");
  searches.write(o.out + "/motion_searches.csv");
}

}  // namespace csm::bench
