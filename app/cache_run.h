// A headless run's side of a shot's cache (app/shot_cache.h): the scene a cache holds, the bake
// that writes one as a run simulates (and resumes one that was stopped), and the run that draws a
// cache's frames without a solver (--from-cache).
#pragma once

#include <string>

#include "app/cli.h"
#include "app/scene_setup.h"
#include "app/shot_cache.h"
#include "sim/run/simulation.h"

namespace csm {

// The scene a cache was baked with, with `options`' --set applied: render parameters change what
// is drawn; a simulation parameter that differs from the bake's is refused (naming it), as is a
// preset given beside the cache. False with the messages.
bool sceneFromCache(const std::string& dir, const Options& options, CacheManifest& manifest,
                    SceneSetup& out, std::string* errors);

// --bake DIR: a frame file after every frame simulated and a resume state every keyframe.
class CacheBake {
 public:
  explicit CacheBake(const Options& options) : dir_(options.bake), quiet_(options.quiet) {}
  bool on() const { return !dir_.empty(); }
  // A new cache for `frames` frames of `sim`'s scene (a cache already in DIR is replaced; a
  // folder that holds anything else is refused).
  bool start(const SceneSetup& scene, const Simulation& sim, const std::string& solver,
             long frames);
  // --resume: `sim`, loaded with the cache's scene, put at the last frame the cache holds whole
  // (from its resume state, stepping again the frames after it, each checked against the cache's
  // bytes). Returns the frame it is at, or -1 having said why. `frames`: the bake's new length
  // (-1 keeps the manifest's).
  long resume(Simulation& sim, const CacheManifest& manifest, long frames);
  // After each frame: its file, and on keyframes (and the last frame) the resume state.
  bool frame(const Simulation& sim);
  // What was written, on stderr.
  void finish() const;

 private:
  std::string dir_;
  bool quiet_;
  CacheManifest manifest_;
  std::vector<glm::vec4> x_;
  long written_ = 0;
  uint64_t bytes_ = 0;
};

// --from-cache DIR (or a cache's folder as the file): the frames --frames A-B names (all of them
// by default) drawn, exported or piped to a video as the run that simulated them did, without
// creating a solver. The exit status.
int runFromCache(const Options& options);

}  // namespace csm
