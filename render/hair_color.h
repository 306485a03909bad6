// The hair's colours: a natural preset (render.hair_color) or the preset's own root and tip
// colours (custom). Display colours, as a colour picker shows them.
#pragma once

#include <glm/vec3.hpp>

#include "render/view_config.h"

namespace csm {

struct HairColors {
  glm::vec3 root, tip;
};

// The colours `color` stands for; custom gives the config's root_color and tip_color.
HairColors hairColors(const RenderConfig& render);
HairColors hairColors(HairColor color, const RenderConfig& custom);

}  // namespace csm
