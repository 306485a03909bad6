// What a large groom costs to import: a cyHair file of 50,000 strands x 100 points (5 M points,
// written here, in centimetres as a DCC tool writes them) read, repaired, fitted, resampled and
// placed on the head (sim/groom/scene_groom.h's buildGroom, each stage timed through its progress),
// then a scene loaded with it and its first frame simulated; the process's peak resident memory
// after each (VmHWM, reset before the import starts).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>

#include "sim/run/make_solver.h"
#include "sim/groom/scene_groom.h"
#include "sim/groom/groom_file.h"
#include "sim/run/simulation.h"
#include "sim/head/head_model.h"
#include "tools/bench/bench.h"
#include "tools/bench/csv.h"

namespace csm::bench {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The process's peak resident set (MiB) since the last resetPeak().
double peakMiB() {
  std::ifstream in("/proc/self/status");
  std::string key;
  while (in >> key) {
    if (key == "VmHWM:") {
      double kb = 0.0;
      in >> kb;
      return kb / 1024.0;
    }
    std::getline(in, key);
  }
  return NAN;
}

void resetPeak() {
  std::ofstream("/proc/self/clear_refs") << "5";
}

// Curly strands of 20-40 cm on a 9 cm scalp, 1.5 m up, in centimetres.
Groom bigGroom(int strands, int points) {
  Groom g;
  g.points.reserve(size_t(strands) * size_t(points));
  std::vector<glm::vec3> strand(static_cast<size_t>(points));
  const double golden = 2.399963229728653;
  for (int s = 0; s < strands; ++s) {
    const double z = 1.0 - 0.9 * (s + 0.5) / strands;  // the upper cap
    const double r = std::sqrt(1.0 - z * z), phi = golden * s;
    const glm::dvec3 n(r * std::cos(phi), z, r * std::sin(phi));
    const double length = 20.0 + 20.0 * ((s * 7919) % 1000) / 1000.0;
    glm::dvec3 p = glm::dvec3(0.0, 150.0, 0.0) + 9.0 * n;
    for (int i = 0; i < points; ++i) {
      strand[size_t(i)] = glm::vec3(p);
      const double t = double(i) / points;
      const glm::dvec3 curl(std::cos(9.0 * t * 6.283 + s), 0.0, std::sin(9.0 * t * 6.283 + s));
      p += length / points *
           glm::normalize(glm::mix(n, glm::dvec3(0, -1, 0), std::min(1.0, 3 * t)) + 0.4 * curl);
    }
    g.addStrand(strand);
  }
  return g;
}

}  // namespace

void runImport(const Options& o) {
  const int strands = o.quick ? 5000 : 50000, points = 100;
  const std::string file = o.out + "/import_" + std::to_string(strands) + "x100.hair";
  {
    std::string error;
    if (!io::writeGroom(file, bigGroom(strands, points), &error)) {
      std::fprintf(stderr, "import: %s\n", error.c_str());
      return;
    }
  }
  Csv csv({"solver", "strands", "points", "file_mb", "stage", "seconds", "peak_mib"});
  std::vector<std::string> solvers = {"cpu"};
  if (o.gpu) solvers.push_back("gpu");
  for (const std::string& name : solvers) {
    auto row = [&](const std::string& stage, double seconds) {
      csv.add(name)
          .add(strands)
          .add(strands * points)
          .add(double(std::filesystem::file_size(file)) / 1e6);
      csv.add(stage).add(seconds).add(peakMiB());
      csv.endRow();
      std::fprintf(stderr, "import %s: %-22s %7.2f s, peak %6.0f MiB\n", name.c_str(),
                   stage.c_str(), seconds, peakMiB());
    };
    Config c = presetConfig(o, "default", 1000000);  // every strand of the file
    c.hairstyle.file = file;
    c.hairstyle.maxParticles = 32;  // as a groom opened directly
    resetPeak();
    row("start", 0.0);
    // The stages as the progress callback names them, each timed to the next.
    std::map<std::string, double> stageSeconds;
    std::string stage;
    auto stageStart = Clock::now();
    auto progress = [&](std::string_view next, double) {
      if (next == stage) return;
      if (!stage.empty()) stageSeconds[stage] += secondsSince(stageStart);
      stage = std::string(next);
      stageStart = Clock::now();
    };
    const auto t0 = Clock::now();
    Groom g;
    GroomReport report;
    std::string error;
    if (!buildGroom(c, *HeadModel::require(c), "", g, &error, &report, progress)) {
      std::fprintf(stderr, "import: %s\n", error.c_str());
      return;
    }
    stageSeconds[stage] += secondsSince(stageStart);
    const double build = secondsSince(t0);
    for (const char* s : {"reading", "fitting", "repairing", "resampling", "placing"})
      row(s, stageSeconds[s]);
    row("import (all)", build);
    std::unique_ptr<Simulation> made = makeSimulation(name, &error);
    if (!made) {
      std::fprintf(stderr, "import: %s\n", error.c_str());
      return;
    }
    Simulation& sim = *made;
    auto t1 = Clock::now();
    if (!sim.load(c, "", &error)) {
      std::fprintf(stderr, "import: %s\n", error.c_str());
      return;
    }
    row("scene load (import again)", secondsSince(t1));
    t1 = Clock::now();
    sim.stepFrame();
    sim.diagnostics().finish();
    row("first frame", secondsSince(t1));
    std::fprintf(stderr, "import %s: %zu strands, %zu points read, %zu particles simulated\n",
                 name.c_str(), sim.counts().strands, report.filePoints, sim.counts().particles);
  }
  csv.write(o.out + "/import.csv");
  std::filesystem::remove(file);
}

}  // namespace csm::bench
