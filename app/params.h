// The preset's one list of parameters: its name and description, the simulation's
// (sim/param/sim_params.h) and the view's (render/view_params.h), in that order. JSON reading and
// writing, --set, --list-params and the panels walk it; no other code names a field by hand.
#pragma once

#include <string_view>
#include <vector>

#include "app/preset_value.h"
#include "sim/param/param_table.h"

namespace csm {

using PresetParam = Param<Preset>;

const std::vector<PresetParam>& params();
const PresetParam* findParam(std::string_view key);

}  // namespace csm
