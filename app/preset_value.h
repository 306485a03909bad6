// What a preset holds, apart from its file: the scene and its look. The one parameter list
// (app/params.h) is declared over it, and the files (app/preset.h) are read and written through
// that list, so this sits below both.
#pragma once

#include <string>

#include "render/view_config.h"
#include "sim/core/config.h"

namespace csm {

struct Preset {
  std::string name = "default";
  std::string description;
  Config scene;     // what the simulation runs
  ViewConfig view;  // the look, the camera, the light
};

}  // namespace csm
