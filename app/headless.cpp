#include "app/headless.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/capture.h"
#include "app/import_progress.h"
#include "sim/run/frame_driver.h"
#include "app/metrics.h"
#include "sim/gpu/pass_profile.h"
#include "gl/caps.h"
#include "gl/context.h"
#include "render/hair_renderer.h"
#include "render/position_source.h"
#include "sim/groom/cyhair.h"
#include "sim/groom/hair_sequence.h"
#include "sim/run/make_solver.h"
#include "sim/run/simulation.h"
#include "sim/solver/stiffness.h"

namespace csm {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

int printDeviceInfo(const Options& options) {
  std::string error;
  std::unique_ptr<gl::HeadlessContext> context = gl::HeadlessContext::create(&error);
  if (!context) {
    std::fprintf(stderr, "csmhair: no OpenGL 4.3 context: %s\n", error.c_str());
    return 1;
  }
  const gl::Caps caps = gl::queryCaps();
  std::printf("context:                    %s\n%s\n", context->platform().c_str(),
              caps.summary().c_str());
  if (caps.software && options.requireGpu) {
    std::fprintf(stderr, "csmhair: --require-gpu: %s is a software renderer, not a GPU\n",
                 caps.renderer.c_str());
    return 1;
  }
  return 0;
}

int runHeadless(const Options& options, const SceneSetup& scene) {
  std::string error;
  // Frames are drawn when something will see them: files, a video, or the metrics' render
  // times. --no-render turns all of it off.
  const bool render = !options.noRender && (!options.outDir.empty() || !options.video.empty() ||
                                            !options.metrics.empty());
  if (options.noRender && !options.video.empty()) {
    std::fprintf(stderr, "csmhair: --video needs frames; drop --no-render\n");
    return 2;
  }
  // Before anything is simulated: a missing ffmpeg or an unwritable directory fails at once.
  std::unique_ptr<VideoPipe> video;
  if (render && !options.video.empty()) {
    const double fps = 1.0 / (double(scene.preset.scene.sim.dt) * options.every);
    video = VideoPipe::open(options.video, options.width, options.height, fps, &error);
    if (!video) {
      std::fprintf(stderr, "csmhair: %s\n", error.c_str());
      return 1;
    }
  }
  if (render && !options.outDir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(options.outDir, ec);
    if (ec || !std::filesystem::is_directory(options.outDir)) {
      std::fprintf(stderr, "csmhair: --out %s: cannot create the directory%s%s\n",
                   options.outDir.c_str(), ec ? ": " : "", ec ? ec.message().c_str() : "");
      return 1;
    }
  }
  if (!options.exportSequence.empty() && !io::prepareSequenceDir(options.exportSequence, &error)) {
    std::fprintf(stderr, "csmhair: --export-hair-sequence: %s\n", error.c_str());
    return 1;
  }
  // One offscreen GL context for both the GPU solver and the renderer.
  std::unique_ptr<gl::HeadlessContext> context;
  if (render || options.solver == "gpu") {
    context = gl::HeadlessContext::create(&error);
    if (!context) {
      std::fprintf(stderr, "csmhair: no OpenGL 4.3 context for %s: %s\n",
                   render ? "rendering (use --no-render to simulate only)" : "the GPU solver",
                   error.c_str());
      return 1;
    }
    if (gl::isSoftwareRenderer(context->renderer())) {
      if (options.requireGpu) {
        std::fprintf(stderr,
                     "csmhair: --require-gpu: the OpenGL context (%s) is a software renderer, "
                     "%s, not a GPU\n",
                     context->platform().c_str(), context->renderer().c_str());
        return 1;
      }
      if (!options.quiet)
        std::fprintf(stderr, "csmhair: warning: %s\n",
                     gl::softwareRendererWarning(context->renderer()).c_str());
    }
  }
  std::unique_ptr<Solver> solver = makeSolver(options.solver, &error);
  if (!solver) {
    std::fprintf(stderr, "csmhair: %s\n", error.c_str());
    return 1;
  }
  Simulation sim(std::move(solver));
  if (!options.quiet) sim.setImportProgress(ImportProgressPrinter());
  if (!sim.load(scene.preset.scene, scene.baseDir, &error)) {
    std::fprintf(stderr, "csmhair: %s\n", error.c_str());
    return 2;
  }
  const long frames = options.frames >= 0 ? options.frames : 60;
  const Groom& groom = sim.groom();
  const bool metrics = !options.metrics.empty();
  const bool writes = render && (!options.outDir.empty() || !options.video.empty());
  // Nothing is read back per frame but the samples: every frame's with --metrics, otherwise
  // one in ten, for the NaN check; a frame written out waits for its own first.
  DriverOptions driving;
  driving.sampleEvery = metrics ? 1 : 10;
  driving.waitForSamples = writes;
  driving.timeToCompletion = metrics;
  // The metrics measure hair-hair contacts in every mode (with hair-hair off, a candidate
  // search per sample outside the frame's timing), so modes compare on the same measures.
  sim.solver().setContactMeasures(metrics);
  FrameDriver driver(sim, driving);
  MetricsLog recorder;
  std::vector<glm::vec4> x;
  auto lastReport = Clock::now();
  const auto start = Clock::now();
  long firstNanFrame = -1;
  auto nanStop = [&] {
    firstNanFrame = driver.nanFrame();
    std::fprintf(stderr,
                 "csmhair: error: the simulation produced NaN at frame %ld (%llu particles); "
                 "stopping\n",
                 firstNanFrame, (unsigned long long)driver.nanParticles());
  };
  const StiffnessInfo stiffness = sim.solver().stiffness();
  if (!options.quiet)
    std::fprintf(
        stderr, "csmhair: %s: %zu strands, %zu particles, solver %s%s%s%s, %ld frames; %s\n",
        scene.source.c_str(), sim.solver().strandCount(), sim.solver().particleCount(),
        std::string(sim.solver().name()).c_str(), sim.solver().variant().empty() ? "" : " (",
        sim.solver().variant().c_str(), sim.solver().variant().empty() ? "" : ")", frames,
        stiffnessText(stiffness).c_str());
  // Said even with --quiet: what the import changed of the file, and hair softer than asked.
  if (const std::string groom = groomReportText(sim.groomReport()); !groom.empty())
    std::fprintf(stderr, "csmhair: warning: %s\n", groom.c_str());
  if (const std::string warning = stiffnessWarning(stiffness); !warning.empty())
    std::fprintf(stderr, "csmhair: warning: %s\n", warning.c_str());

  std::unique_ptr<HairRenderer> renderer;
  std::unique_ptr<CaptureTarget> target;
  PositionSource positions;
  long written = 0;
  double lastRenderMs = 0.0;
  if (render) {
    renderer = HairRenderer::create(&error);
    if (!renderer) {
      std::fprintf(stderr, "csmhair: %s\n", error.c_str());
      return 1;
    }
    target = std::make_unique<CaptureTarget>(options.width, options.height);
    if (!options.quiet)
      std::fprintf(stderr, "csmhair: rendering %zu strands (%zu simulated) at %dx%d on %s%s%s\n",
                   drawnStrandCount(sim.solver().strandCount(), scene.preset.view.render),
                   sim.solver().strandCount(), options.width, options.height,
                   context->renderer().c_str(), options.outDir.empty() ? "" : " into ",
                   options.outDir.c_str());
  }
  // Frames whose hair-hair lists did not fit the solver's buffers: said at the end, never silent.
  // (ContactStats::add keeps the running count of overflows and the most crowded segments.)
  ContactStats seen;
  auto takeSamples = [&] {
    for (const FrameSample& sample : driver.takeSamples()) {
      seen.add(sample.contacts);
      if (metrics) recorder.addSample(sample);
    }
  };
  gpu::pass_profile::clear();  // CSM_PASS_PROFILE: the frames only, not the set-up
  long simulated = 0;
  long exported = 0;  // frames written by --export-hair-sequence
  for (long f = 0; f < frames; ++f) {
    driver.step();
    ++simulated;
    if (metrics) recorder.addFrame(driver.lastStepMs(), sim.solver().stageTimes());
    takeSamples();
    if (driver.stopped()) {
      nanStop();
      break;
    }
    if (!options.exportSequence.empty() && (f + 1) % options.every == 0) {
      sim.solver().readPositions(x);
      ++exported;
      if (!io::writeSequenceFrame(options.exportSequence, exported, groom, x, &error)) {
        std::fprintf(stderr, "csmhair: --export-hair-sequence: %s\n", error.c_str());
        return 1;
      }
    }
    if (renderer && (f + 1) % options.every == 0) {
      const unsigned buffer = positions.update(sim.solver());
      const auto r0 = Clock::now();
      renderer->render(frameViewOf(sim, scene.preset.view, buffer, target->width(),
                                   target->height(), target->framebuffer()));
      if (metrics) {
        CaptureTarget::waitForGpu();
        lastRenderMs = std::chrono::duration<double, std::milli>(Clock::now() - r0).count();
        recorder.addRender(lastRenderMs, renderer->stageTimes());
      }
      if (writes) {
        const std::vector<std::uint8_t> rgb = target->readRgb();
        ++written;
        if (!options.outDir.empty()) {
          char name[32];
          std::snprintf(name, sizeof name, "frame_%05ld.png", written);
          const std::string path = (std::filesystem::path(options.outDir) / name).string();
          if (!writePng(path, target->width(), target->height(), rgb, &error)) {
            std::fprintf(stderr, "csmhair: %s\n", error.c_str());
            return 1;
          }
        }
        if (video && !video->write(rgb)) {
          video->close(&error);
          std::fprintf(stderr, "csmhair: %s: ffmpeg stopped taking frames%s%s\n",
                       options.video.c_str(), error.empty() ? "" : ": ", error.c_str());
          return 1;
        }
      }
    }
    const auto now = Clock::now();
    if (!options.quiet && (now - lastReport > std::chrono::seconds(2) || f + 1 == frames)) {
      const double elapsed = std::chrono::duration<double>(now - start).count();
      std::fprintf(stderr, "  frame %ld/%ld  %.1f ms/frame", f + 1, frames,
                   1000.0 * elapsed / double(simulated));
      if (driver.latestSample())
        std::fprintf(stderr, "  max strain %.4f (frame %ld)",
                     driver.latestSample()->accuracy.maxStrain, driver.latestSample()->frame);
      std::fprintf(stderr, "  %.0f s elapsed", elapsed);
      if (renderer && metrics)
        std::fprintf(stderr, "  render %.1f ms  %ld written", lastRenderMs, written);
      std::fputc('\n', stderr);
      lastReport = now;
    }
  }
  // The samples still in flight: the last frames' NaN check and measures.
  if (firstNanFrame < 0) {
    driver.drain();
    takeSamples();
    if (driver.stopped()) nanStop();
  }
  const std::string passes = gpu::pass_profile::table(simulated);
  if (!passes.empty())
    std::fprintf(stderr, "csmhair: CSM_PASS_PROFILE, %ld frames, each pass between two waits:\n%s",
                 simulated, passes.c_str());
  if (seen.overflows > 0)
    std::fprintf(stderr,
                 "csmhair: warning: the candidate pairs of %llu frames did not fit the solver's "
                 "buffers: those frames kept the list before them (and counted no crossings)\n",
                 (unsigned long long)seen.overflows);
  if (seen.crowded > 0)
    std::fprintf(stderr,
                 "csmhair: warning: up to %llu segments a frame were in too dense a crowd for "
                 "the strand contacts (over 2,048 candidate pairs, or a grid cell the search "
                 "could not finish): some or all of their contacts were missing\n",
                 (unsigned long long)seen.crowded);
  if (sim.carriedFrames() > 0)
    std::fprintf(
        stderr,
        "csmhair: note: in %ld frames a move of the head moved its roots faster than %.0f m/s: the "
        "hair went with it, rigidly, for the part beyond\n",
        sim.carriedFrames(), kMaxRootSpeed);
  if (seen.oversize > 0)
    std::fprintf(stderr,
                 "csmhair: warning: up to %llu segments a frame were too long for the collision "
                 "grid's cells or not finite: they had no strand contacts\n",
                 (unsigned long long)seen.oversize);
  if (!options.exportHair.empty()) {
    // The final strands in world space, as a cyHair file for other tools.
    sim.solver().readPositions(x);
    const Groom out = io::posedGroom(groom, x);
    if (!io::writeCyHair(options.exportHair, out, &error)) {
      std::fprintf(stderr, "csmhair: %s\n", error.c_str());
      return 1;
    }
    if (!options.quiet)
      std::fprintf(stderr, "csmhair: wrote %zu strands to %s\n", out.strandCount(),
                   options.exportHair.c_str());
  }
  if (exported > 0 && !options.quiet)
    std::fprintf(stderr, "csmhair: wrote %ld frames of %zu strands into %s\n", exported,
                 groom.strandCount(), options.exportSequence.c_str());
  if (video) {
    if (!video->close(&error)) {
      std::fprintf(stderr, "csmhair: %s\n", error.c_str());
      return 1;
    }
    if (!options.quiet)
      std::fprintf(stderr, "csmhair: wrote %ld frames to %s\n", written, options.video.c_str());
  }
  if (!options.metrics.empty()) {
    const Config& c = sim.config();
    RunDescription d;
    d.preset = scene.preset.name;
    d.source = scene.source;
    d.config = c;
    d.stiffness = stiffness;
    d.strands = sim.solver().strandCount();
    d.particles = sim.solver().particleCount();
    d.solver = std::string(sim.solver().name());
    d.solverVariant = sim.solver().variant();
    d.groom = sim.groomReport();
    d.device = options.solver == "gpu" && context ? context->renderer() : std::string("cpu");
    nlohmann::json meta = describeRun(d);
    meta["mode"] = "headless";
    meta["head_carried_frames"] = sim.carriedFrames();
    if (renderer) {
      meta["drawn_strands"] =
          drawnStrandCount(sim.solver().strandCount(), scene.preset.view.render);
      meta["render_size"] = {options.width, options.height};
      meta["render_samples"] = renderer->samples();
      meta["gl_renderer"] = context->renderer();
    }
    if (!recorder.write(options.metrics, meta, &error)) {
      std::fprintf(stderr, "csmhair: %s\n", error.c_str());
      return 1;
    }
  }
  return firstNanFrame >= 0 ? 1 : 0;
}

}  // namespace csm
