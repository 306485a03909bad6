// Checks of a scene beyond single values' ranges: between parameters, and of the machine's
// capacity. Presets run them on reading; the viewer on every change. Neither reads a file: the
// head (head.mesh) is read and checked once, when the scene's HeadModel is built (setupScene,
// --validate, or Simulation::load for a scene opened later).
#pragma once

#include <string>
#include <vector>

#include "sim/core/config.h"

namespace csm {

// Checks that hold between parameters. One message a problem, naming the keys.
std::vector<std::string> crossCheck(const Config& c);

// Refuses scenes the machine cannot hold, before anything is allocated. Empty when fine.
std::string checkCapacity(const Config& c);

}  // namespace csm
