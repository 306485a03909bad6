// The headless run: no window; simulate, measure, and (with a renderer) capture frames.
// Used by CI and render farms.
#pragma once

#include "app/cli.h"
#include "app/scene_setup.h"

namespace csm {

// Returns the process exit status.
int runHeadless(const Options& options, const SceneSetup& scene);

}  // namespace csm
