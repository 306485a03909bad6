// The wind field u(x, t): direction x strength x (1 + gusts(t)) + spatial turbulence.
// shaders/sim/wind.glsl evaluates the same formula in float; keep the two in step.
#pragma once

#include <glm/vec3.hpp>

#include "sim/core/config.h"

namespace csm {

glm::dvec3 windVelocity(const WindConfig& wind, const glm::dvec3& x, double t);

}  // namespace csm
