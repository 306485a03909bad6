#include "app/cache_run.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "app/frame_outputs.h"
#include "app/frame_view.h"
#include "app/import_progress.h"
#include "app/params.h"
#include "sim/motion/clip.h"
#include "sim/run/cache_files.h"

namespace csm {
namespace {

namespace fs = std::filesystem;

// The cache's own files in `dir` (frames, the resume state, what a stopped write left), so that a
// new bake starts clean; anything else in the folder is kept.
void clearCacheFiles(const std::string& dir) {
  std::error_code ec;
  for (const fs::path& sub : {fs::path(dir), fs::path(dir) / "frames"}) {
    for (const fs::directory_entry& e : fs::directory_iterator(sub, ec)) {
      const std::string name = e.path().filename().string();
      const bool ours = (name.rfind("frame_", 0) == 0 && name.find(".bin") != std::string::npos) ||
                        name.rfind(shot_cache::kStateName, 0) == 0 ||
                        name.rfind(shot_cache::kManifestName, 0) == 0;
      if (ours && e.is_regular_file(ec)) fs::remove(e.path(), ec);
    }
  }
}

bool emptyOrMissing(const std::string& dir) {
  std::error_code ec;
  return !fs::exists(dir, ec) || (fs::is_directory(dir, ec) && fs::is_empty(dir, ec));
}

std::vector<glm::vec4> asVec4(const std::vector<glm::vec3>& p) {
  std::vector<glm::vec4> out(p.size());
  for (size_t i = 0; i < p.size(); ++i) out[i] = glm::vec4(p[i], 1.0f);
  return out;
}

// The largest distance between a frame stepped again and the cache's (m); 0 when every float is
// the same.
double largestDifference(const std::vector<glm::vec4>& stepped,
                         const std::vector<glm::vec3>& cached) {
  double worst = 0.0;
  for (size_t i = 0; i < cached.size(); ++i) {
    const glm::vec3 s(stepped[i]);
    if (std::memcmp(&s, &cached[i], sizeof s) != 0)
      worst = std::max(worst, std::max(1e-30, double(glm::length(s - cached[i]))));
  }
  return worst;
}

}  // namespace

bool sceneFromCache(const std::string& dir, const Options& options, CacheManifest& manifest,
                    SceneSetup& out, std::string* errors) {
  auto fail = [&](const std::string& why) {
    if (errors) *errors = why + "\n";
    return false;
  };
  if (!options.preset.empty() && options.preset != dir)
    return fail("csmhair: " + options.preset + ": a cache draws the preset it was baked with (" +
                dir + "); give no preset beside it");
  std::string error;
  if (!shot_cache::readManifest(dir, manifest, &error)) return fail(error);
  out.preset = manifest.preset;
  out.baseDir = manifest.baseDir;
  out.source = dir + " (baked from " + manifest.source + ")";
  // The --set pairs on the baked preset, in order: a simulation parameter they leave other than
  // it was baked is refused, naming it.
  Preset set = manifest.preset;
  for (const auto& [key, value] : options.sets)
    if (const PresetParam* p = findParam(key)) paramFromText(*p, set, value);  // applySets checks
  set.view = manifest.preset.view;  // the look, the camera, the light: drawn as asked
  set.name = manifest.preset.name;
  set.description = manifest.preset.description;
  std::string refused;
  for (const auto& [key, value] : options.sets) {
    const PresetParam* p = findParam(key);
    if (!p || valueText(*p, set) == valueText(*p, manifest.preset) ||
        refused.find("--set " + key + "=") != std::string::npos)
      continue;
    refused += "--set " + key + "=" + value + ": a simulation parameter (the cache " + dir +
               " was baked with " + key + "=" + valueText(*p, manifest.preset) +
               "); a cache draws the frames it holds: bake again to change it\n";
  }
  if (!refused.empty()) {
    if (errors) *errors = refused;
    return false;
  }
  return applySets(options.sets, out, errors);
}

bool CacheBake::start(const SceneSetup& scene, const Simulation& sim, const std::string& solver,
                      long frames) {
  auto fail = [&](const std::string& why) {
    std::fprintf(stderr, "csmhair: --bake %s: %s\n", dir_.c_str(), why.c_str());
    return false;
  };
  std::error_code ec;
  if (fs::exists(dir_, ec) && !fs::is_directory(dir_, ec))
    return fail("a file, not a folder: give a new or empty folder");
  if (!shot_cache::isCache(dir_) && !emptyOrMissing(dir_))
    return fail("the folder holds files and no cache: give a new or empty folder");
  clearCacheFiles(dir_);
  CacheManifest& m = manifest_;
  m.preset = scene.preset;
  m.source = scene.source;
  m.baseDir = scene.baseDir;
  m.solver = solver;
  m.frames = frames;
  m.strands = sim.groom().strandCount();
  m.particles = sim.groom().pointCount();
  m.drawnStrands = sim.drawnStrands();
  m.drawnPoints = sim.followers() ? sim.followers()->drawn.pointCount() : m.particles;
  m.groomHash = groomHash(sim.scene());
  std::string error;
  if (!shot_cache::inputsOf(m.preset, m.baseDir, m.inputs, &error) ||
      !shot_cache::writeManifest(dir_, m, &error))
    return fail(error);
  return true;
}

long CacheBake::resume(Simulation& sim, const CacheManifest& manifest, long frames) {
  auto fail = [&](const std::string& why) {
    std::fprintf(stderr, "csmhair: --resume %s: %s\n", dir_.c_str(), why.c_str());
    return -1L;
  };
  manifest_ = manifest;
  std::string error;
  if (!shot_cache::matches(manifest_, sim.scene(), &error)) return fail(error);
  if (frames >= 0 && frames != manifest_.frames) {
    manifest_.frames = frames;
    if (!shot_cache::writeManifest(dir_, manifest_, &error)) return fail(error);
  }
  long complete = shot_cache::completeFrames(dir_, manifest_);
  if (fs::exists(shot_cache::statePath(dir_))) {
    SimulationState state;
    if (!cache::readState(shot_cache::statePath(dir_), state, &error)) return fail(error);
    if (state.frame > complete)
      return fail("its resume state is of frame " + std::to_string(state.frame) +
                  ", after the frames it holds whole (1-" + std::to_string(complete) +
                  "): bake again");
    state.generation = sim.generation();
    state.config = sim.config();
    if (!sim.restore(state, &error)) return fail(error);
  }
  // The frames after the state, stepped again: each the cache's bytes, or the cache is not this
  // build's and driver's.
  FrameRecording::Shown cached;
  while (sim.frame() < complete) {
    const long f = sim.frame() + 1;
    if (!cache::readFrame(shot_cache::framePath(dir_, f), f, manifest_.particles, cached, &error)) {
      std::fprintf(stderr, "csmhair: --resume: %s: written again from here\n", error.c_str());
      complete = f - 1;
      break;
    }
    sim.stepFrame();
    if (sim.stopped()) return fail("the simulation produced NaN at frame " + std::to_string(f));
    sim.readPositions(x_);
    const double differs = largestDifference(x_, cached.positions);
    if (differs > 0.0)
      return fail("frame " + std::to_string(f) + " stepped again is not the cache's (up to " +
                  std::to_string(differs) +
                  " m apart): it was baked by another build or driver; bake again");
    if (f % manifest_.keyframeEvery == 0) {
      SimulationState state;
      sim.save(state);
      if (!cache::writeState(shot_cache::statePath(dir_), state, &error)) return fail(error);
    }
  }
  if (!quiet_)
    std::fprintf(stderr, "csmhair: --resume: the cache holds frames 1-%ld of %ld; going on\n",
                 complete, manifest_.frames);
  return sim.frame();
}

bool CacheBake::frame(const Simulation& sim) {
  std::string error;
  FrameRecording::Shown shown;
  shown.frame = sim.frame();
  shown.time = sim.time();
  shown.head = sim.headPose();
  sim.readPositions(x_);
  shown.positions.resize(x_.size());
  for (size_t i = 0; i < x_.size(); ++i) shown.positions[i] = glm::vec3(x_[i]);
  if (!cache::writeFrame(shot_cache::framePath(dir_, shown.frame), shown, &error)) {
    std::fprintf(stderr, "csmhair: --bake: %s\n", error.c_str());
    return false;
  }
  ++written_;
  bytes_ += cache::frameBytes(shown.positions.size());
  if (shown.frame % manifest_.keyframeEvery == 0 || shown.frame == manifest_.frames) {
    SimulationState state;
    sim.save(state);
    if (!cache::writeState(shot_cache::statePath(dir_), state, &error)) {
      std::fprintf(stderr, "csmhair: --bake: %s\n", error.c_str());
      return false;
    }
  }
  return true;
}

void CacheBake::finish() const {
  if (quiet_ || !on()) return;
  std::fprintf(stderr,
               "csmhair: baked %ld frames into %s (%.2f MB a frame: %zu particles of %zu "
               "strands)\n",
               written_, dir_.c_str(),
               written_ > 0 ? 1e-6 * double(bytes_) / double(written_) : 0.0, manifest_.particles,
               manifest_.strands);
}

int runFromCache(const Options& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::string& dir = options.fromCache;
  CacheManifest m;
  SceneSetup scene;
  std::string error;
  if (!sceneFromCache(dir, options, m, scene, &error)) {
    std::fputs(error.c_str(), stderr);
    return 2;
  }
  if (!options.metrics.empty()) {
    std::fprintf(stderr, "csmhair: --metrics measures a simulation; a cache draws without one\n");
    return 2;
  }
  const long first = options.firstFrame;
  const long last = options.frames >= 0 ? options.frames : m.frames;
  const long complete = shot_cache::completeFrames(dir, m);
  if (last > complete) {
    const std::string stopped = complete < m.frames
                                    ? " of the bake's " + std::to_string(m.frames) +
                                          " (its bake stopped: --bake DIR --resume goes on)"
                                    : "";
    std::fprintf(stderr, "csmhair: --frames %ld-%ld: the cache %s holds frames 1-%ld%s\n", first,
                 last, dir.c_str(), complete, stopped.c_str());
    return 2;
  }
  const bool render = !options.noRender;
  FrameOutputs out(options);
  if (!out.open(render, double(scene.preset.scene.sim.dt))) return 1;
  VideoOutput& video = out.video;
  const ImageFiles& images = out.images;
  HairExport& hair = out.hair;
  std::unique_ptr<gl::HeadlessContext> context;
  if (render) {
    context = openContext(options, true);
    if (!context) return 1;
  }
  // The hair as the bake grew it: the same head, groom and followers, and no solver.
  GrownScene grown;
  std::function<void(std::string_view, double)> progress;
  if (!options.quiet) progress = ImportProgressPrinter();
  if (!growScene(scene.preset.scene, scene.baseDir, scene.head.get(), progress, grown, &error) ||
      !shot_cache::matches(m, grown, &error)) {
    std::fprintf(stderr, "csmhair: %s: %s\n", dir.c_str(), error.c_str());
    return 2;
  }
  std::unique_ptr<FrameCapture> capture;
  if (render && (images.on() || video.on())) {
    capture = FrameCapture::create(options);
    if (!capture) return 1;
  }
  if (!options.quiet)
    std::fprintf(stderr,
                 "csmhair: %s: frames %ld-%ld of %ld (baked by the %s solver), %zu strands drawn "
                 "(%zu simulated)%s%s\n",
                 dir.c_str(), first, last, m.frames, m.solver.c_str(),
                 drawnStrandCount(grown.drawnStrands(), scene.preset.view.render), m.strands,
                 capture ? " on " : "", capture ? context->renderer().c_str() : "");
  FrameRecording::Shown frame;
  Pose torso;  // the torso under the frame's head
  std::vector<glm::vec4> positions;
  long drawn = 0;
  for (long f = first; f <= last; ++f) {
    if (!keptFrame(options, f)) continue;
    if (!cache::readFrame(shot_cache::framePath(dir, f), f, m.particles, frame, &error)) {
      std::fprintf(stderr, "csmhair: %s\n", error.c_str());
      return 2;
    }
    positions = asVec4(frame.positions);
    torso = torsoPoseAt(scene.preset.scene, grown.clip.get(), frame.time, frame.head);
    if (!hair.writeFrame(keptIndex(options, f), grown, positions, BodyPose{frame.head, torso}))
      return 1;
    if (!capture) continue;
    const unsigned buffer = capture->upload().upload(positions);
    capture->draw(frameViewOf(scene.preset.scene, grown, 1, frame.head, torso, scene.preset.view,
                              buffer, capture->width(), capture->height(), capture->framebuffer()),
                  false);
    const std::vector<std::uint8_t> rgb = capture->readBack();
    if (images.on() &&
        !images.write(keptIndex(options, f), capture->width(), capture->height(), rgb))
      return 1;
    if (video.on() && !video.write(rgb)) return 1;
    ++drawn;
  }
  if (hair.on() && !positions.empty() &&
      !hair.finish(grown, positions, BodyPose{frame.head, torso}))
    return 1;
  if (video.on() && !video.close(capture->framesReadBack())) return 1;
  if (!options.quiet)
    std::fprintf(stderr, "csmhair: drew %ld frames from %s in %.1f s, no solver\n", drawn,
                 dir.c_str(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return 0;
}

}  // namespace csm
