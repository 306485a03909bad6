#include "app/headless.h"

#include <chrono>
#include <cstdio>

#include "app/metrics.h"
#include "sim/head.h"
#include "sim/io/cyhair.h"
#include "sim/metrics.h"
#include "sim/simulation.h"

namespace csm {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

int runHeadless(const Options& options, const SceneSetup& scene) {
  std::string error;
  std::unique_ptr<Solver> solver = makeSolver(options.solver, &error);
  if (!solver) {
    std::fprintf(stderr, "csmhair: %s\n", error.c_str());
    return 1;
  }
  Simulation sim(std::move(solver));
  if (!sim.load(scene.config, scene.baseDir, &error)) {
    std::fprintf(stderr, "csmhair: %s\n", error.c_str());
    return 2;
  }
  const long frames = options.frames >= 0 ? options.frames : 60;
  const Groom& groom = sim.groom();
  const std::vector<double> rest = restLengths(groom);
  MetricsRecorder recorder;
  std::vector<glm::vec4> x, v;
  auto lastReport = Clock::now();
  const auto start = Clock::now();
  long firstNanFrame = -1;
  if (!options.quiet)
    std::fprintf(stderr, "csmhair: %s: %zu strands, %zu particles, solver %s, %ld frames\n",
                 scene.source.c_str(), sim.solver().strandCount(), sim.solver().particleCount(),
                 std::string(sim.solver().name()).c_str(), frames);
  for (long f = 0; f < frames; ++f) {
    const auto t0 = Clock::now();
    sim.stepFrame();
    sim.solver().finish();
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    sim.solver().readPositions(x);
    sim.solver().readVelocities(v);
    const std::vector<Sphere> spheres = worldSpheres(sim.config().head.spheres, sim.headPose());
    const Accuracy acc = measureAccuracy(x, v, groom, rest, spheres, sim.config().sim.pinned);
    recorder.addFrame(ms, acc, sim.solver().stageTimes(), sim.solver().contactStats());
    if (acc.nanCount > 0 && firstNanFrame < 0) {
      firstNanFrame = f + 1;
      std::fprintf(stderr,
                   "csmhair: error: the simulation produced NaN at frame %ld (%llu particles); "
                   "stopping\n",
                   firstNanFrame, (unsigned long long)acc.nanCount);
      break;
    }
    const auto now = Clock::now();
    if (!options.quiet && (now - lastReport > std::chrono::seconds(2) || f + 1 == frames)) {
      const double elapsed = std::chrono::duration<double>(now - start).count();
      std::fprintf(stderr, "  frame %ld/%ld  %.1f ms/frame  max strain %.4f  %.0f s elapsed\n",
                   f + 1, frames, recorder.simMean(), acc.maxStrain, elapsed);
      lastReport = now;
    }
  }
  if (!options.exportHair.empty()) {
    // The final strands in world space, as a cyHair file for other tools.
    sim.solver().readPositions(x);
    Groom out;
    out.first = groom.first;
    out.points.reserve(x.size());
    for (const glm::vec4& p : x) out.points.emplace_back(p);
    out.color = groom.color;
    out.thickness = groom.thickness;
    if (!io::writeCyHair(options.exportHair, out, &error)) {
      std::fprintf(stderr, "csmhair: %s\n", error.c_str());
      return 1;
    }
    if (!options.quiet)
      std::fprintf(stderr, "csmhair: wrote %zu strands to %s\n", out.strandCount(),
                   options.exportHair.c_str());
  }
  if (!options.metrics.empty()) {
    const Config& c = sim.config();
    nlohmann::json meta = {
        {"preset", c.name},
        {"source", scene.source},
        {"strands", sim.solver().strandCount()},
        {"particles", sim.solver().particleCount()},
        {"frame_dt", c.sim.dt},
        {"substeps", c.sim.substeps},
        {"stiffness_window", c.sim.stiffnessWindow},
        {"collision_mode", c.collision.mode == CollisionMode::Off    ? "off"
                           : c.collision.mode == CollisionMode::Head ? "head"
                                                                     : "full"},
        {"solver", std::string(sim.solver().name())},
        {"groom",
         {{"file_strands", sim.groomReport().fileStrands},
          {"file_points", sim.groomReport().filePoints},
          {"simulated_particles", sim.groomReport().simulatedPoints},
          {"resample_saved_particles", sim.groomReport().savedPoints()}}},
        {"device", options.solver == "cpu" ? "cpu" : "gpu"},
    };
    if (!recorder.write(options.metrics, meta, &error)) {
      std::fprintf(stderr, "csmhair: %s\n", error.c_str());
      return 1;
    }
  }
  return firstNanFrame >= 0 ? 1 : 0;
}

}  // namespace csm
