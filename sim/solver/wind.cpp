// The GLSL twin: shaders/sim/wind.glsl.
#include "sim/solver/wind.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace csm {

glm::dvec3 windVelocity(const WindConfig& wind, const glm::dvec3& x, double t) {
  if (wind.strength <= 0.0f) return glm::dvec3(0.0);
  const glm::dvec3 dir = glm::normalize(glm::dvec3(wind.direction));
  const double w = 2.0 * M_PI * wind.gustFrequency;
  // Two incommensurate sines: gusts that do not repeat visibly.
  const double gust = 0.6 * std::sin(w * t) + 0.4 * std::sin(2.7 * w * t + 1.7);
  const double speed = wind.strength * std::max(0.0, 1.0 + wind.gusts * gust);
  // Divergence-free-looking swirl from sines of the other coordinates, drifting with time.
  const double k = 2.0 * M_PI / wind.turbulenceScale;
  const double drift = 1.3 * w + 0.7;
  const glm::dvec3 swirl(
      std::sin(k * x.y + drift * t) + std::sin(k * x.z - 0.6 * drift * t),
      std::sin(k * x.z + 1.1 * drift * t + 2.0) + std::sin(k * x.x - 0.8 * drift * t + 1.0),
      std::sin(k * x.x + 0.9 * drift * t + 4.0) + std::sin(k * x.y - 1.2 * drift * t + 3.0));
  return dir * speed + 0.5 * wind.turbulence * wind.strength * swirl;
}

}  // namespace csm
