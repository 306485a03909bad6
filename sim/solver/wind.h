// The wind field u(x, t): direction x strength x (1 + gusts(t)) + spatial turbulence, in double
// from the text shaders/sim/wind.glsl compiles in float (windField,
// shaders/sim/shared_functions.glsl).
#pragma once

#include <glm/vec3.hpp>

#include "sim/core/config.h"

namespace csm {

glm::dvec3 windVelocity(const WindConfig& wind, const glm::dvec3& x, double t);
// The fastest the field blows anywhere (m/s): strength x (1 + gusts) with the gusts at their
// peak, plus the turbulence's swirl at most 0.5 turbulence strength x 2 sqrt(3).
double windPeakSpeed(const WindConfig& wind);

}  // namespace csm
