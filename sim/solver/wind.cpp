#include "sim/solver/wind.h"

#include <glm/geometric.hpp>

#include "sim/base/shared_functions.h"

namespace csm {

glm::dvec3 windVelocity(const WindConfig& wind, const glm::dvec3& x, double t) {
  if (wind.strength <= 0.0f) return glm::dvec3(0.0);
  const glm::dvec3 dir = glm::normalize(glm::dvec3(wind.direction));
  return shared::windField(dir, wind.strength, wind.gusts, wind.gustFrequency, wind.turbulence,
                           wind.turbulenceScale, x, t);
}

}  // namespace csm
