// csmhair: every strand of a head of hair simulated with Chain Shape Matching.
#include <cstdio>

#include "app/cache_run.h"
#include "app/cli.h"
#include "app/headless.h"
#include "app/scene_setup.h"
#include "app/params.h"
#include "app/preset.h"
#include "sim/head/head_model.h"
#include "sim/motion/clip.h"
#ifdef CSM_HAVE_VIEWER
#include "app/viewer.h"
#endif

namespace {

int listParams() {
  const csm::Preset defaults = csm::defaultPreset();
  std::string group;
  for (const csm::PresetParam& p : csm::params()) {
    if (p.group != group) {
      group = p.group;
      std::printf("\n[%s]\n", group.c_str());
    }
    std::printf("  %-32s %s  default %s%s\n      %s\n", std::string(p.key).c_str(),
                csm::describeType(p).c_str(), csm::valueText(p, defaults).c_str(),
                p.effect == csm::Effect::Rebuild ? "  (regrows the hair)" : "",
                std::string(p.description).c_str());
  }
  return 0;
}

int validate(const std::vector<std::string>& files) {
  int status = 0;
  for (const std::string& f : files) {
    csm::Preset c = csm::defaultPreset();
    csm::PresetErrors errors;
    // The head too, as the scene that loads the preset reads it: its file and line when bad.
    std::string headError;
    if (csm::loadPreset(f, c, errors) && !csm::HeadModel::build(c.scene, &headError))
      errors.messages.push_back(f + ": " + headError);
    // And the motion clip, relative to the preset as the scene reads it.
    std::string clipError;
    if (errors.messages.empty() && !c.scene.motion.clip.empty() &&
        !csm::MotionClip::load(c.scene.motion, c.scene.head.meshDir, glm::dvec3(c.scene.head.pivot),
                               &clipError))
      errors.messages.push_back(f + ": " + clipError);
    if (errors.messages.empty()) {
      std::printf("%s: ok (%d strands)\n", f.c_str(), c.scene.hairstyle.strands);
    } else {
      std::fputs(errors.text().c_str(), stderr);
      status = 2;
    }
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  std::string error;
  std::optional<csm::Options> options = csm::parseCommandLine(argc, argv, &error);
  if (!options) {
    std::fprintf(stderr, "csmhair: %s\n", error.c_str());
    return 2;
  }
  if (options->help) {
    std::fputs(csm::usageText().c_str(), stdout);
    return 0;
  }
  if (options->listParams) return listParams();
  if (options->validateMode) return validate(options->validate);
  if (options->info) return csm::printDeviceInfo(*options);

  // A shot's cache opened as the file: drawn from, not simulated.
  if (options->fromCache.empty() && csm::shot_cache::isCache(options->preset))
    options->fromCache = options->preset;
  if (!options->fromCache.empty() && options->headless) return csm::runFromCache(*options);
  csm::SceneSetup scene;
#ifdef CSM_HAVE_VIEWER
  if (!options->fromCache.empty()) {
    // The window opens the cache's scene with its frames on the timeline.
    csm::CacheManifest manifest;
    if (!csm::sceneFromCache(options->fromCache, *options, manifest, scene, &error)) {
      std::fputs(error.c_str(), stderr);
      return 2;
    }
    return csm::runViewer(*options, scene, "");
  }
#endif
  if (options->resume) {
    csm::CacheManifest manifest;
    if (!options->headless) {
      std::fprintf(stderr, "csmhair: --resume runs headless: add --headless\n");
      return 2;
    }
    if (!csm::sceneFromCache(options->bake, *options, manifest, scene, &error)) {
      std::fputs(error.c_str(), stderr);
      return 2;
    }
    return csm::runHeadless(*options, scene, &manifest);
  }
  if (!csm::setupScene(*options, scene, &error)) {
    std::fputs(error.c_str(), stderr);
#ifdef CSM_HAVE_VIEWER
    // The window opens anyway, on the built-in scene, and shows the messages.
    if (!options->headless && options->savePreset.empty()) {
      csm::SceneSetup builtIn;
      builtIn.preset = csm::defaultPreset();
      builtIn.source = "<built-in default preset>";
      return csm::runViewer(*options, builtIn, error);
    }
#endif
    return 2;
  }
  if (!options->savePreset.empty()) {
    if (!csm::savePreset(options->savePreset, scene.preset, &error)) {
      std::fprintf(stderr, "csmhair: %s\n", error.c_str());
      return 1;
    }
    return 0;
  }
  if (!options->headless) {
#ifdef CSM_HAVE_VIEWER
    return csm::runViewer(*options, scene, "");
#else
    std::fprintf(stderr,
                 "csmhair: the window is not part of this build (CSM_BUILD_VIEWER=OFF); use "
                 "--headless\n");
    return 1;
#endif
  }
  return csm::runHeadless(*options, scene);
}
