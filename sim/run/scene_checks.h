// Checks of a scene beyond single values' ranges: between parameters, and of the machine's
// capacity. Presets run them on reading; the viewer on every change.
#pragma once

#include <string>
#include <vector>

#include "sim/core/config.h"
#include "sim/head/head_model.h"

namespace csm {

// Checks that hold between parameters. One message a problem, naming the keys. head.mesh is
// read and checked, unless `loaded` (the running scene's head, built and checked when the scene
// loaded) was read from that file: an edit that leaves the mesh alone reads nothing from disk.
std::vector<std::string> crossCheck(const Config& c, const HeadModel* loaded = nullptr);

// Refuses scenes the machine cannot hold, before anything is allocated. Empty when fine.
std::string checkCapacity(const Config& c);

}  // namespace csm
