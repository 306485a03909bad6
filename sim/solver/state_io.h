// The CPU solvers' state (double, a glm::dvec3 a particle) to and from the Solver interface's
// float layout (sim/core/hair_state.h: vec4, w 1 for a position and 0 for a velocity): one
// conversion for CpuSolver and the baselines, so both read and write the same bytes.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace csm {

inline void readDoublePositions(const std::vector<glm::dvec3>& x, std::vector<glm::vec4>& out) {
  out.resize(x.size());
  for (size_t i = 0; i < x.size(); ++i) out[i] = glm::vec4(glm::vec3(x[i]), 1.0f);
}

inline void readDoubleVelocities(const std::vector<glm::dvec3>& v, std::vector<glm::vec4>& out) {
  out.resize(v.size());
  for (size_t i = 0; i < v.size(); ++i) out[i] = glm::vec4(glm::vec3(v[i]), 0.0f);
}

// As Solver::writeState: the particles given overwrite the first of x and v; more are ignored,
// fewer leave the rest as they were.
inline void writeDoubleState(const std::vector<glm::vec4>& positions,
                             const std::vector<glm::vec4>& velocities, std::vector<glm::dvec3>& x,
                             std::vector<glm::dvec3>& v) {
  for (size_t i = 0; i < x.size() && i < positions.size(); ++i)
    x[i] = glm::dvec3(glm::vec3(positions[i]));
  for (size_t i = 0; i < v.size() && i < velocities.size(); ++i)
    v[i] = glm::dvec3(glm::vec3(velocities[i]));
}

}  // namespace csm
