// The shortest rotation between two directions, in float (the followers) or double (the follow
// hairs made at import).
#pragma once

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace csm {

// The shortest rotation taking unit a to unit b; none where they are opposed (no one shortest).
template <class T>
glm::qua<T> shortestTurn(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
  const T c = glm::dot(a, b);
  if (!(c > T(-0.9999))) return glm::qua<T>(T(1), T(0), T(0), T(0));
  const glm::vec<3, T> v = glm::cross(a, b);
  return glm::normalize(glm::qua<T>(T(1) + c, v.x, v.y, v.z));
}

}  // namespace csm
