// Small scenes shared by the tests (the GPU suite runs the same against the CPU reference).
#pragma once

#include <vector>

#include <glm/vec4.hpp>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/groom/hairstyle.h"
#include "sim/head/head_model.h"
#include "sim/verify/scenes.h"

namespace csm::test {

// A few hundred strands of the default hairstyle: quick, but with every feature in play.
inline Config smallScene(int strands = 60) {
  return smallSceneConfig({.strands = strands});
}

inline Groom growFor(const Config& c) {
  return growHairstyle(c, *HeadModel::require(c));
}

// The strand of each of the groom's points (the layout every solver keeps).
inline std::vector<uint32_t> strandOf(const Groom& g) {
  std::vector<uint32_t> out(g.pointCount());
  for (size_t s = 0; s < g.strandCount(); ++s)
    for (uint32_t i = g.first[s]; i < g.first[s + 1]; ++i) out[i] = uint32_t(s);
  return out;
}

// A solver's read-back positions in double, as the CPU measures take them.
inline std::vector<glm::dvec3> toDouble(const std::vector<glm::vec4>& x) {
  std::vector<glm::dvec3> out;
  out.reserve(x.size());
  for (const glm::vec4& p : x) out.emplace_back(glm::vec3(p));
  return out;
}

}  // namespace csm::test
