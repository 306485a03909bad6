// The headless run: no window; simulate, measure, and (with a renderer) capture frames.
// Used by CI and render farms.
#pragma once

#include "app/cli.h"
#include "app/scene_setup.h"

namespace csm {

struct CacheManifest;

// Returns the process exit status. `resumed`: --bake DIR --resume, the manifest of DIR's cache
// whose scene `scene` is (app/cache_run.h's sceneFromCache).
int runHeadless(const Options& options, const SceneSetup& scene,
                const CacheManifest* resumed = nullptr);

// --info: the headless context's device and limits on stdout. 1 when there is no context,
// or with --require-gpu when it is a software renderer.
int printDeviceInfo(const Options& options);

}  // namespace csm
