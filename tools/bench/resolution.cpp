// Resolution: one cantilever strand (kCantileverLength) simulated with 8 to 32 particles. The
// stiffness window w counts particles, so a fixed w spans a shorter piece of strand as particles
// are added and the strand gets softer; a window given as a length (windowForLength) keeps it.
#include <cstdio>

#include <glm/geometric.hpp>

#include "tools/bench/bench.h"
#include "tools/bench/csv.h"

namespace csm::bench {

void runResolution(const Options& o) {
  const double length = kCantileverLength;
  const std::vector<int> counts =
      o.quick ? std::vector<int>{8, 16, 32} : std::vector<int>{8, 12, 16, 24, 32};
  const double swing = 1.0, settle = o.quick ? 1.5 : 2.0;
  // The window length that gives w = 2 at 16 particles.
  const double windowLength = 2.0 * length / 15.0;
  struct Line {
    std::string family, label;
    Setting setting;
    bool byLength = false;
  };
  std::vector<Line> lines;
  auto csm = [](int w) {
    Setting s;
    s.solver = "csm";
    s.window = w;
    return s;
  };
  lines.push_back({"CSM", "w = 2 particles", csm(2)});
  lines.push_back({"CSM", "w = 4 particles", csm(4)});
  lines.push_back({"CSM", "w = 3.3 cm (2 at 16 particles)", csm(2), true});
  lines.push_back({"CSM", "w = 6.7 cm (4 at 16 particles)", csm(4), true});
  for (float length : {0.02f, 0.04f}) {
    Setting s = csm(2);
    s.model = StiffnessModel::Calibrated;
    s.windowLength = length;
    s.substeps = 1;  // as many as the stiffness needs
    s.maxSubsteps = 256;
    char label[64];
    std::snprintf(label, sizeof label, "%g cm window, B %g", 100.0 * length, s.bendingStiffness);
    lines.push_back({"CSM calibrated", label, s});
  }
  {
    Setting s;
    s.solver = "ms-explicit";
    s.substeps = 48;
    lines.push_back({"MS explicit", "EA 0.05 N, 48 substeps", s});
    s.solver = "ms-implicit";
    s.substeps = 4;
    lines.push_back({"MS implicit", "EA 0.05 N", s});
    s.solver = "pbd";
    s.params.iterations = 8;
    lines.push_back({"PBD", "8 iterations", s});
    s.solver = "ftl";
    lines.push_back({"FTL (DFTL 0.9)", "no bending", s});
  }
  struct Job {
    int line, particles, window;
    CantileverRun run;  // the swing
    double sagMm = NAN;
  };
  std::vector<Job> jobs;
  for (int l = 0; l < int(lines.size()); ++l)
    for (int n : counts) {
      int w = -1;
      if (lines[l].byLength)
        w = windowForLength(windowLength * lines[l].setting.window / 2.0, length / (n - 1));
      jobs.push_back({l, n, w, {}});
    }
  std::fprintf(stderr, "resolution: %zu runs\n", jobs.size());
  parallelFor(int(jobs.size()), o.threads, [&](int i) {
    Job& j = jobs[i];
    j.run = runCantilever(lines[j.line].setting, j.particles, j.window, swing);
    j.sagMm = runCantilever(lines[j.line].setting, j.particles, j.window, settle, kSettleDamping,
                            kSagGravity)
                  .sagMm;
  });
  Csv csv({"family", "label", "particles", "window", "sag_mm", "swing_tip_rms_vs_finest_mm"});
  for (const Job& j : jobs) {
    const Job& finest = jobs[(j.line + 1) * counts.size() - 1];
    double sum = 0.0;
    size_t count = 0;
    if (j.run.finite && finest.run.finite)
      for (size_t f = 0; f < std::min(j.run.tip.size(), finest.run.tip.size()); ++f) {
        const glm::dvec3 d = j.run.tip[f] - finest.run.tip[f];
        sum += glm::dot(d, d);
        ++count;
      }
    const Line& line = lines[j.line];
    const bool csm = line.setting.isCsm();
    csv.add(line.family).add(line.label).add(j.particles);
    csv.add(csm ? double(j.window > 0 ? j.window : line.setting.window) : NAN);
    csv.add(j.sagMm).add(count ? 1000.0 * std::sqrt(sum / double(count)) : NAN);
    csv.endRow();
    std::fprintf(stderr, "  %-16s %-32s n=%2d sag %6.1f mm\n", line.family.c_str(),
                 line.label.c_str(), j.particles, j.sagMm);
  }
  csv.write(o.out + "/resolution.csv");
}

}  // namespace csm::bench
