#include "sim/solver.h"

namespace csm {

void Solver::carry(const Pose& by) {
  std::vector<glm::vec4> x, v;
  readPositions(x);
  readVelocities(v);
  for (glm::vec4& p : x) p = glm::vec4(glm::vec3(by.apply(glm::dvec3(glm::vec3(p)))), p.w);
  for (glm::vec4& u : v) u = glm::vec4(glm::vec3(by.rotation * glm::dvec3(glm::vec3(u))), u.w);
  writeState(x, v);
}

}  // namespace csm
