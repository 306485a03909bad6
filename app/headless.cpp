#include "app/headless.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/cache_run.h"
#include "app/frame_outputs.h"
#include "app/frame_view.h"
#include "app/import_progress.h"
#include "app/metrics.h"
#include "app/sim_frame.h"
#include "gl/caps.h"
#include "gl/context.h"
#include "gl/pass_profile.h"
#include "render/hair_renderer.h"
#include "sim/core/config.h"
#include "shaders/sim/shared_constants.glsl"
#include "sim/run/make_solver.h"
#include "sim/run/simulation.h"
#include "sim/solver/stiffness.h"

namespace csm {
namespace {

using Clock = std::chrono::steady_clock;

// Frames are drawn when something will see them: files, a video, or the metrics' render
// times. --no-render turns all of it off.
bool drawsFrames(const Options& options) {
  return !options.noRender &&
         (!options.outDir.empty() || !options.video.empty() || !options.metrics.empty());
}

// The scene loaded on the solver --solver names; null, having said why, with the exit status
// in `status` (2: the scene, 1: anything else).
std::unique_ptr<Simulation> loadSimulation(const Options& options, const SceneSetup& scene,
                                           int* status) {
  std::string error;
  std::unique_ptr<Simulation> sim = makeSimulation(options.solver, &error);
  if (!sim) {
    std::fprintf(stderr, "csmhair: %s\n", error.c_str());
    *status = 1;
    return nullptr;
  }
  if (!options.quiet) sim->setImportProgress(ImportProgressPrinter());
  if (!sim->load(scene.preset.scene, scene.baseDir, &error, scene.head)) {
    std::fprintf(stderr, "csmhair: %s\n", error.c_str());
    *status = 2;
    return nullptr;
  }
  return sim;
}

// What runs, on stderr: the counts and the solver (not with --quiet), and, even with --quiet,
// what the import changed of the file and hair softer than asked.
void sayScene(const Options& options, const SceneSetup& scene, const Simulation& sim, long frames) {
  const StiffnessInfo stiffness = sim.diagnostics().stiffness();
  const std::string variant = sim.diagnostics().variant();
  if (!options.quiet)
    std::fprintf(
        stderr, "csmhair: %s: %zu strands, %zu particles, solver %s%s%s%s, %ld frames; %s\n",
        scene.source.c_str(), sim.counts().strands, sim.counts().particles,
        std::string(sim.solverName()).c_str(), variant.empty() ? "" : " (", variant.c_str(),
        variant.empty() ? "" : ")", frames, stiffnessText(stiffness).c_str());
  if (const std::string head = sim.head().summary(); !head.empty() && !options.quiet)
    std::fprintf(stderr, "csmhair: %s\n", head.c_str());
  if (sim.clip() && !options.quiet)
    std::fprintf(stderr,
                 "csmhair: motion: %s; DFTL %.2g while it drives (sim.dftl %.2g, "
                 "motion.dftl %.2g)\n",
                 sim.clip()->summary().c_str(), dftlOf(scene.preset.scene),
                 scene.preset.scene.sim.dftl, scene.preset.scene.motion.dftl);
  if (const std::string groom = groomReportText(sim.groomReport()); !groom.empty())
    std::fprintf(stderr, "csmhair: warning: %s\n", groom.c_str());
  if (const std::string warning = stiffnessWarning(stiffness); !warning.empty())
    std::fprintf(stderr, "csmhair: warning: %s\n", warning.c_str());
}

// Nothing is read back per frame but the samples: every frame's with --metrics, otherwise one
// in ten, for the NaN check; a frame written out (`writes`) waits for its own first.
Sampling samplingOf(bool metrics, bool writes) {
  Sampling sampling;
  sampling.every = metrics ? 1 : 10;
  sampling.wait = writes;
  sampling.timeToCompletion = metrics;
  return sampling;
}

// --metrics: every frame's wall and stage times, every frame's sample, the drawn frames'
// times, and what ran.
class MetricsOutput {
 public:
  explicit MetricsOutput(const Options& options) : options_(options) {}
  bool on() const { return !options_.metrics.empty(); }
  void addFrame(double ms, const std::vector<StageTime>& stages) {
    if (on()) log_.addFrame(ms, stages);
  }
  void addSample(const FrameSample& sample) {
    if (on()) log_.addSample(sample);
  }
  void addRender(double ms, const std::vector<StageTime>& stages) { log_.addRender(ms, stages); }
  // Seconds from the start of the run to the scene loaded (the groom built, the guides bound, the
  // solver reset).
  void setStartup(double seconds) { startup_ = seconds; }
  // `context` and `renderer` are null when the run had none.
  bool write(const SceneSetup& scene, Simulation& sim, const gl::HeadlessContext* context,
             const HairRenderer* renderer) const {
    if (!on()) return true;
    SimFrame figures;
    takeFigures(sim, figures);
    nlohmann::json meta = describeRun(runDescription(
        scene, figures,
        options_.solver == "gpu" && context ? context->renderer() : std::string("cpu")));
    meta["mode"] = "headless";
    meta["startup_s"] = startup_;
    if (const FollowerBinding* followers = sim.followers()) {
      // The last frame's followers, made on the CPU as the exports make them.
      std::vector<glm::vec4> guides, drawn;
      sim.readPositions(guides);
      const FollowerStats stats = sim.drawnPositions(guides, drawn);
      meta["followers"] = {{"guides", followers->guideCount()},
                           {"drawn_strands", followers->drawn.strandCount()},
                           {"far_followers", followers->farFollowers},
                           {"pushed_points", stats.pushed},
                           {"deepest_inside_m", stats.deepest}};
    }
    meta["head_carried_frames"] = sim.carriedFrames();
    meta["root_peak_speed"] = sim.peakRootSpeed();
    meta["rigid_peak_speed"] = sim.peakRigidSpeed();
    meta["explained_peak_speed"] = sim.explainedPeakSpeed();
    if (const MotionClip* clip = sim.clip()) {
      const ClipFacts& f = clip->facts();
      meta["motion"] = {{"clip", scene.preset.scene.motion.clip},
                        {"frames", f.frames},
                        {"frame_time", f.frameTime},
                        {"unit", f.unit},
                        {"scale", f.scale},
                        {"up", std::string(1, f.up)},
                        {"facing", f.facing},
                        {"head_joint", f.headJoint},
                        {"chest_joint", f.chestJoint},
                        {"travel_m", f.travel},
                        {"clip_head_peak_speed", f.peakHeadSpeed},
                        {"clip_cuts", f.cuts.size()},
                        {"cuts_carried", sim.clipCuts()}};
    }
    if (renderer) {
      meta["drawn_strands"] = drawnStrandCount(sim.drawnStrands(), scene.preset.view.render);
      meta["render_size"] = {options_.width, options_.height};
      meta["render_samples"] = renderer->samples();
      meta["gl_renderer"] = context->renderer();
    }
    std::string error;
    if (!log_.write(options_.metrics, meta, &error)) {
      std::fprintf(stderr, "csmhair: %s\n", error.c_str());
      return false;
    }
    return true;
  }

 private:
  const Options& options_;
  MetricsLog log_;
  double startup_ = 0.0;
};

// What is drawn, on stderr unless --quiet: the strands, the size, the device, the folder.
void sayRendering(const Options& options, const SceneSetup& scene, const Simulation& sim,
                  const gl::HeadlessContext& context) {
  if (options.quiet) return;
  std::fprintf(stderr, "csmhair: rendering %zu strands (%zu simulated) at %dx%d on %s%s%s\n",
               drawnStrandCount(sim.drawnStrands(), scene.preset.view.render), sim.counts().strands,
               options.width, options.height, context.renderer().c_str(),
               options.outDir.empty() ? "" : " into ", options.outDir.c_str());
}

// CSM_PASS_PROFILE=1: the compute passes of the GPU solver and of the renderer over the run's
// `frames` frames, each timed between two waits (gl/pass_profile.h).
void sayPassProfile(long frames) {
  const std::string passes = gl::pass_profile::table(frames);
  if (!passes.empty())
    std::fprintf(stderr, "csmhair: CSM_PASS_PROFILE, %ld frames, each pass between two waits:\n%s",
                 frames, passes.c_str());
}

// A line on stderr every two seconds and at the last frame: the frame, its wall time, the
// latest measure and, with --metrics, the drawn frames.
class Progress {
 public:
  Progress(const Options& options, long frames) : quiet_(options.quiet), frames_(frames) {}
  // The last frame drawn took `ms` (with --metrics).
  void rendered(double ms) { renderMs_ = ms; }
  // After frame `f` (from 1).
  void frame(long f, long simulated, const Simulation& sim, const FrameCapture* capture,
             bool metrics) {
    const auto now = Clock::now();
    if (quiet_ || (now - lastReport_ <= std::chrono::seconds(2) && f != frames_)) return;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    std::fprintf(stderr, "  frame %ld/%ld  %.1f ms/frame", f, frames_,
                 1000.0 * elapsed / double(simulated));
    if (sim.latestSample())
      std::fprintf(stderr, "  max strain %.4f (frame %ld)", sim.latestSample()->accuracy.maxStrain,
                   sim.latestSample()->frame);
    std::fprintf(stderr, "  %.0f s elapsed", elapsed);
    if (capture && metrics)
      std::fprintf(stderr, "  render %.1f ms  %ld written", renderMs_, capture->framesReadBack());
    std::fputc('\n', stderr);
    lastReport_ = now;
  }

 private:
  bool quiet_;
  long frames_;
  double renderMs_ = 0.0;
  Clock::time_point start_ = Clock::now(), lastReport_ = start_;
};

// What the frames' samples said that the run must not keep silent, said at its end: lists that
// did not fit the solver's buffers, crowds too dense for the contacts, segments too long for
// the grid (ContactStats::add keeps the running counts), and head moves carried rigidly. In a
// mode without strand contacts the lists are only the crossings measure's (--metrics): what they
// missed is said of that measure, not of contacts the mode does not have.
class RunWarnings {
 public:
  void add(const FrameSample& sample) { seen_.add(sample.contacts); }
  void say(const Simulation& sim) const {
    if (!strandContacts(sim.config().collision.mode)) {
      sayMeasure();
    } else {
      if (seen_.overflows > 0)
        std::fprintf(stderr,
                     "csmhair: warning: the candidate pairs of %llu frames did not fit the "
                     "solver's buffers (collision.contact_memory_mb %d MiB, or the device's "
                     "limit): those frames kept the list before them (and counted no "
                     "crossings); raise collision.contact_memory_mb or simulate fewer strands "
                     "(hairstyle.guides)\n",
                     (unsigned long long)seen_.overflows, sim.config().collision.contactMemoryMb);
      if (seen_.crowded > 0)
        std::fprintf(stderr,
                     "csmhair: warning: up to %llu segments a frame were in too dense a crowd "
                     "for the strand contacts (over 2,048 candidate pairs, or a grid cell the "
                     "search could not finish): some or all of their contacts were missing\n",
                     (unsigned long long)seen_.crowded);
      if (seen_.oversize > 0)
        std::fprintf(stderr,
                     "csmhair: warning: up to %llu segments a frame were too long for the "
                     "collision grid's cells or not finite: they had no strand contacts\n",
                     (unsigned long long)seen_.oversize);
    }
    if (sim.clipCuts() > 0)
      std::fprintf(stderr,
                   "csmhair: note: the clip cut %ld times (a frame further from the one before "
                   "than a person moves): the hair went with the head over each cut\n",
                   sim.clipCuts());
    if (sim.carriedFrames() > 0)
      std::fprintf(stderr,
                   "csmhair: note: in %ld frames a move of the head moved its roots faster than "
                   "%.0f m/s: the hair went with it, rigidly, for the part beyond\n",
                   sim.carriedFrames(), kMaxRootSpeed);
  }

 private:
  // The crossings measure's lists (a mode without strand contacts): what they could not count.
  void sayMeasure() const {
    const uint64_t missed = seen_.crowded + seen_.oversize;
    if (seen_.measureStride > 1)
      std::fprintf(stderr,
                   "csmhair: note: the hair-hair measures (--metrics) searched 1 strand in %u "
                   "(hair of over %u particles): their pair counts are the sample's times %u\n",
                   unsigned(seen_.measureStride), unsigned(CSM_MEASURED_PARTICLES),
                   unsigned(seen_.measureStride * seen_.measureStride));
    if (seen_.overflows > 0)
      std::fprintf(stderr,
                   "csmhair: note: the hair-crossings measure (--metrics) counted no crossings in "
                   "%llu frames: their candidate pairs did not fit the solver's buffers\n",
                   (unsigned long long)seen_.overflows);
    if (missed > 0)
      std::fprintf(stderr,
                   "csmhair: note: the hair-crossings measure (--metrics) left out up to %llu "
                   "segments a frame (in a crowd of over 2,048 candidate pairs, or too long for "
                   "its grid): their crossings are not counted\n",
                   (unsigned long long)missed);
  }

  ContactStats seen_;
};

// The samples the simulation has taken, to the warnings and the metrics.
void takeSamples(Simulation& sim, RunWarnings& warnings, MetricsOutput& metrics) {
  for (const FrameSample& sample : sim.takeSamples()) {
    warnings.add(sample);
    metrics.addSample(sample);
  }
}

void sayNan(const Simulation& sim) {
  std::fprintf(stderr,
               "csmhair: error: the simulation produced NaN at frame %ld (%llu particles); "
               "stopping\n",
               sim.nanFrame(), (unsigned long long)sim.nanParticles());
}

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

int runHeadless(const Options& options, const SceneSetup& scene, const CacheManifest* resumed) {
  const auto start = std::chrono::steady_clock::now();
  const bool render = drawsFrames(options);
  if (options.noRender && !options.video.empty()) {
    std::fprintf(stderr, "csmhair: --video needs frames; drop --no-render\n");
    return 2;
  }
  FrameOutputs out(options);
  if (!out.open(render, double(scene.preset.scene.sim.dt))) return 1;
  VideoOutput& video = out.video;
  const ImageFiles& images = out.images;
  HairExport& hair = out.hair;
  CacheBake bake(options);

  // A resumed bake runs on the solver that baked it.
  Options run = options;
  if (resumed) run.solver = resumed->solver;
  std::unique_ptr<gl::HeadlessContext> context;
  if (render || run.solver == "gpu") {
    context = openContext(run, render);
    if (!context) return 1;
  }
  int status = 0;
  std::unique_ptr<Simulation> sim = loadSimulation(run, scene, &status);
  if (!sim) return status;
  // A clip plays once through unless --frames says otherwise.
  long frames = options.frames >= 0     ? options.frames
                : sim->clipFrames() > 0 ? sim->clipFrames()
                                        : 60;
  if (resumed && options.frames < 0) frames = resumed->frames;
  MetricsOutput metrics(options);
  metrics.setStartup(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  // No frame is written out before its NaN check: the images, the video, the cache.
  const bool writes = (render && (images.on() || video.on())) || bake.on();
  // The metrics measure hair-hair contacts in every mode (with hair-hair off, a candidate
  // search per sample outside the frame's timing), so modes compare on the same measures.
  sim->diagnostics().setContactMeasures(metrics.on());
  sim->setSampling(samplingOf(metrics.on(), writes));
  Progress progress(options, frames);
  sayScene(run, scene, *sim, frames);
  long from = 0;  // the frame the run starts at
  if (resumed) {
    from = bake.resume(*sim, *resumed, options.frames);
    if (from < 0) return 1;
  } else if (bake.on() && !bake.start(scene, *sim, run.solver, frames)) {
    return 1;
  }

  std::unique_ptr<FrameCapture> capture;
  if (render) {
    capture = FrameCapture::create(options);
    if (!capture) return 1;
    sayRendering(options, scene, *sim, *context);
  }

  RunWarnings warnings;
  bool nan = false;
  gl::pass_profile::clear();  // CSM_PASS_PROFILE: the frames only, not the set-up
  long simulated = 0;
  std::vector<glm::vec4> positions;
  for (long f = from + 1; f <= frames; ++f) {
    sim->stepFrame();
    ++simulated;
    metrics.addFrame(sim->lastStepMs(), sim->diagnostics().stageTimes());
    takeSamples(*sim, warnings, metrics);
    if (sim->stopped()) {
      sayNan(*sim);
      nan = true;
      break;
    }
    if (bake.on() && !bake.frame(*sim)) return 1;
    if (!keptFrame(options, f)) {
      progress.frame(f, simulated, *sim, capture.get(), metrics.on());
      continue;
    }
    if (!options.exportSequence.empty()) {
      sim->readPositions(positions);
      if (!hair.writeFrame(keptIndex(options, f), sim->scene(), positions,
                           BodyPose{sim->headPose(), sim->torsoPose()}))
        return 1;
    }
    if (capture) {
      const unsigned buffer = positionsToDraw(*sim, capture->upload());
      const double ms = capture->draw(frameViewOf(*sim, scene.preset.view, buffer, capture->width(),
                                                  capture->height(), capture->framebuffer()),
                                      metrics.on());
      if (metrics.on()) metrics.addRender(ms, capture->renderer().stageTimes());
      progress.rendered(ms);
      if (writes) {
        const std::vector<std::uint8_t> rgb = capture->readBack();
        if (images.on() &&
            !images.write(keptIndex(options, f), capture->width(), capture->height(), rgb))
          return 1;
        if (video.on() && !video.write(rgb)) return 1;
      }
    }
    progress.frame(f, simulated, *sim, capture.get(), metrics.on());
  }
  // The samples still in flight: the last frames' NaN check and measures.
  if (!nan) {
    sim->drainSamples();
    takeSamples(*sim, warnings, metrics);
    if (sim->stopped()) {
      sayNan(*sim);
      nan = true;
    }
  }
  sayPassProfile(simulated);
  warnings.say(*sim);
  bake.finish();
  if (hair.on()) {
    sim->readPositions(positions);
    if (!hair.finish(sim->scene(), positions, BodyPose{sim->headPose(), sim->torsoPose()}))
      return 1;
  }
  if (video.on() && !video.close(capture->framesReadBack())) return 1;
  if (!metrics.write(scene, *sim, context.get(), capture ? &capture->renderer() : nullptr))
    return 1;
  return nan ? 1 : 0;
}

}  // namespace csm
