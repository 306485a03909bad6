// The view's parameters (sim/param/param_table.h): every field of render/view_config.h that a
// preset sets, declared once here; the program lifts them into the preset's list (app/params.h).
#pragma once

#include <vector>

#include "render/view_config.h"
#include "sim/param/param_table.h"

namespace csm {

const std::vector<Param<ViewConfig>>& viewParams();

}  // namespace csm
