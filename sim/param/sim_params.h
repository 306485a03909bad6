// The simulation's parameters (sim/param/param_table.h): every field of sim/core/config.h's Config
// that a preset sets, declared once here. The program lifts them, with the view's, into the
// preset's one list (app/params.h).
#pragma once

#include <string_view>
#include <vector>

#include "sim/core/config.h"
#include "sim/param/param_table.h"

namespace csm {

const std::vector<Param<Config>>& simParams();
const Param<Config>* findSimParam(std::string_view key);

// True when going from `a` to `b` changes a parameter whose change regrows the hair.
bool needsRegrow(const Config& a, const Config& b);
// True when no parameter differs between `a` and `b`.
bool sameScene(const Config& a, const Config& b);

}  // namespace csm
