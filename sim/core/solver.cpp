#include "sim/core/solver.h"

#include "sim/base/state_bytes.h"

namespace csm {

void Solver::carry(const Pose& by) {
  std::vector<glm::vec4> x, v;
  readPositions(x);
  readVelocities(v);
  for (glm::vec4& p : x) p = glm::vec4(glm::vec3(by.apply(glm::dvec3(glm::vec3(p)))), p.w);
  for (glm::vec4& u : v) u = glm::vec4(glm::vec3(by.rotation * glm::dvec3(glm::vec3(u))), u.w);
  writeState(x, v);
}

void Solver::saveState(SolverState& out) {
  std::vector<glm::vec4> x, v;
  readPositions(x);
  readVelocities(v);
  StateWriter w(out.bytes);
  w.put(particleCount());
  w.putVector(x);
  w.putVector(v);
}

bool Solver::restoreState(const SolverState& in, std::string* error) {
  StateReader r(in.bytes);
  std::vector<glm::vec4> x, v;
  if (!r.expectCount(particleCount(), "particles", error) || !r.getVector(x, particleCount()) ||
      !r.getVector(v, particleCount()) || !r.done(error)) {
    if (error && error->empty()) *error = "a saved state of another size";
    return false;
  }
  writeState(x, v);
  return true;
}

}  // namespace csm
