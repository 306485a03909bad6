// From the command line to a validated scene: the preset (or the built-in default, or a groom
// file with default settings) with every --set applied.
#pragma once

#include <memory>
#include <string>

#include "app/cli.h"
#include "app/preset_value.h"
#include "sim/head/head_model.h"

namespace csm {

struct SceneSetup {
  Preset preset;
  std::string baseDir;  // where relative paths in the preset point
  std::string source;   // what the scene came from, for messages
  // The scene's head, built from the preset once (head.mesh read, checked and sampled; spheres
  // fitted): the scene that loads it (Simulation::load) uses this one, reading nothing again.
  std::shared_ptr<const HeadModel> head;
};

// Returns false with messages (one a line) naming the file and JSON path, or the --set; a
// head.mesh that cannot be read is named with its file and line.
bool setupScene(const Options& options, SceneSetup& out, std::string* errors);

// Applies the --set pairs to `out.preset`, checks the scene and builds its head: setupScene's
// second half, for a scene that comes from elsewhere (a shot's cache).
bool applySets(const std::vector<std::pair<std::string, std::string>>& sets, SceneSetup& out,
               std::string* errors);

// True when `path` names a groom file rather than a preset.
bool isGroomFile(const std::string& path);

}  // namespace csm
