// csmhair-bench: regenerates the speed-against-accuracy CSV and charts of docs/BENCHMARKS.md.
//
//   csmhair-bench [--quick] [--gpu] [--out DIR] [--only SECTION]... [--threads N] [--no-charts]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "tools/bench/bench.h"
#include "gl/context.h"
#include "sim/run/make_solver.h"

#ifndef CSM_SOURCE_DIR
#define CSM_SOURCE_DIR "."
#endif

namespace {

using namespace csm;
using namespace csm::bench;

const char* kSections[] = {"methods",       "stability", "resolution", "region_sums", "scaling",
                           "scene_choices", "window",    "recording",  "torture",     "soak",
                           "import",        "motion",    "soft_hair"};

void usage(FILE* f) {
  std::fprintf(f,
               "csmhair-bench: speed against accuracy for CSM and the baselines.\n\n"
               "usage: csmhair-bench [options]\n\n"
               "  --quick          a smaller run (about a minute); writes to ./bench-quick\n"
               "                   unless --out is given\n"
               "  --gpu            create a headless GL context and include the GPU solver\n"
               "  --out DIR        where CSV and charts go (default: docs/charts of the source)\n"
               "  --only SECTION   run only this section (repeatable): methods, stability,\n"
               "                   resolution, region_sums, scaling, scene_choices, window,\n"
               "                   recording,\n"
               "                   torture, soak, import, motion, soft_hair (these five\n"
               "                   run only when named)\n"
               "  --threads N      workers for accuracy runs (default 2; timings run alone)\n"
               "  --no-charts      write CSV only; do not run scripts/charts.py\n"
               "  --help           this text\n");
}

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(colon + 2);
    }
  return "unknown";
}

std::string commandOutput(const std::string& cmd) {
  std::string out;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  o.source = CSM_SOURCE_DIR;
  std::string command = "csmhair-bench";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    command += " " + a;
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "csmhair-bench: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      command += std::string(" ") + argv[i + 1];
      return argv[++i];
    };
    if (a == "--quick") {
      o.quick = true;
    } else if (a == "--gpu") {
      o.gpu = true;
    } else if (a == "--out") {
      o.out = value();
    } else if (a == "--only") {
      const std::string s = value();
      bool known = false;
      for (const char* k : kSections) known |= s == k;
      if (!known) {
        std::fprintf(stderr, "csmhair-bench: unknown section \"%s\"\n", s.c_str());
        usage(stderr);
        return 2;
      }
      o.only.push_back(s);
    } else if (a == "--threads") {
      o.threads = std::atoi(value().c_str());
      if (o.threads < 1) {
        std::fprintf(stderr, "csmhair-bench: --threads needs a number >= 1\n");
        return 2;
      }
    } else if (a == "--no-charts") {
      o.charts = false;
    } else if (a == "--help" || a == "-h") {
      usage(stdout);
      return 0;
    } else {
      std::fprintf(stderr, "csmhair-bench: unknown option %s\n", a.c_str());
      usage(stderr);
      return 2;
    }
  }
  if (o.out.empty()) o.out = o.quick ? "bench-quick" : o.source + "/docs/charts";
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  if (ec) {
    std::fprintf(stderr, "csmhair-bench: cannot create %s: %s\n", o.out.c_str(),
                 ec.message().c_str());
    return 1;
  }

  nlohmann::json meta = {
      {"command", command},
      {"quick", o.quick},
      {"cores", std::thread::hardware_concurrency()},
      {"cpu", cpuModel()},
      {"threads", o.threads},
      {"commit", commandOutput("git -C '" + o.source + "' rev-parse --short HEAD 2>/dev/null")},
  };
  std::unique_ptr<gl::HeadlessContext> context;
  if (o.gpu) {
    std::string error;
    context = gl::HeadlessContext::create(&error);
    std::unique_ptr<Simulation> probe = context ? makeSimulation("gpu", &error) : nullptr;
    if (!probe) {
      std::fprintf(stderr, "csmhair-bench: no GPU solver (%s); measuring the CPU only\n",
                   error.c_str());
      o.gpu = false;
    } else {
      meta["gl_renderer"] = context->renderer();
      meta["gl_version"] = context->version();
    }
  }

  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  nlohmann::json seconds = nlohmann::json::object();
  auto section = [&](const char* name, void (*fn)(const Options&)) {
    if (!o.wants(name)) return;
    const auto t0 = Clock::now();
    fn(o);
    seconds[name] = std::chrono::duration<double>(Clock::now() - t0).count();
    std::fprintf(stderr, "%s: %.0f s\n", name, seconds[name].get<double>());
  };
  section("methods", runMethods);
  section("stability", runStability);
  section("resolution", runResolution);
  section("region_sums", runRegionSums);
  section("scaling", runScaling);
  section("scene_choices", runSceneChoices);
  section("window", runWindow);
  section("recording", runRecording);
  // Reliability, not speed (docs/RELIABILITY.md): only when asked for by name.
  auto named = [&](const char* name) {
    return std::find(o.only.begin(), o.only.end(), name) != o.only.end();
  };
  if (named("torture")) section("torture", runTortureMap);
  if (named("soak")) section("soak", runSoakSection);
  if (named("import")) section("import", runImport);
  if (named("motion")) section("motion", runMotion);
  if (named("soft_hair")) section("soft_hair", runSoftHair);
  meta["seconds"] = seconds;
  meta["seconds_total"] = std::chrono::duration<double>(Clock::now() - start).count();
  {
    std::ofstream f(o.out + "/meta.json");
    f << meta.dump(2) << "\n";
  }
  std::fprintf(stderr, "simulation: %.0f s; CSV in %s\n", meta["seconds_total"].get<double>(),
               o.out.c_str());
  if (o.charts) {
    // Only the sections run: the others' charts stay as their runs left them.
    std::string cmd = "/usr/bin/python3 '" + o.source + "/scripts/charts.py' '" + o.out + "'";
    for (const std::string& s : o.only) cmd += " " + s;
    std::fprintf(stderr, "%s\n", cmd.c_str());
    const int rc = std::system(cmd.c_str());
    if (rc != 0) {
      std::fprintf(stderr, "csmhair-bench: charts.py failed (status %d)\n", rc);
      return 1;
    }
  }
  std::fprintf(stderr, "total: %.0f s\n",
               std::chrono::duration<double>(Clock::now() - start).count());
  return 0;
}
