// A point read back from a solver (a vec4 a particle, sim/core/solver.h) as the measures take it:
// in double, and whether it is finite. One copy for sim/verify's measures, torture map and soak.
#pragma once

#include <cmath>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace csm {

inline glm::dvec3 d3(const glm::vec4& p) {
  return {p.x, p.y, p.z};
}

inline bool finite(const glm::vec4& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

}  // namespace csm
