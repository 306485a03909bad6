#include "sim/solver/wind.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "sim/base/shared_functions.h"

namespace csm {

glm::dvec3 windVelocity(const WindConfig& wind, const glm::dvec3& x, double t) {
  if (wind.strength <= 0.0f) return glm::dvec3(0.0);
  const glm::dvec3 dir = glm::normalize(glm::dvec3(wind.direction));
  return shared::windField(dir, wind.strength, wind.gusts, wind.gustFrequency, wind.turbulence,
                           wind.turbulenceScale, x, t);
}

double windPeakSpeed(const WindConfig& wind) {
  if (wind.strength <= 0.0f) return 0.0;
  return double(wind.strength) *
         (1.0 + double(wind.gusts) + std::sqrt(3.0) * double(wind.turbulence));
}

}  // namespace csm
