#include "sim/core/hair_state.h"

#include <glm/geometric.hpp>

namespace csm {

HairState makeHairState(const Groom& groom, const SimConfig& sim, const Pose& head) {
  HairState st;
  const size_t n = groom.pointCount();
  st.strandFirst = groom.first;
  st.particleStrand.resize(n);
  st.rest.resize(n);
  st.position.resize(n);
  st.velocity.assign(n, glm::vec4(0.0f));
  st.tipHeld = groom.tipHeld;
  st.weight = groom.weight;
  for (size_t s = 0; s < groom.strandCount(); ++s) {
    const uint32_t a = groom.first[s], b = groom.first[s + 1];
    for (uint32_t i = a; i < b; ++i) {
      double len = 0.0;
      if (i > a) len += 0.5 * glm::length(groom.points[i] - groom.points[i - 1]);
      if (i + 1 < b) len += 0.5 * glm::length(groom.points[i + 1] - groom.points[i]);
      const float mass = float(std::max(len, 1e-6) * sim.density);
      st.particleStrand[i] = uint32_t(s);
      st.rest[i] = glm::vec4(groom.points[i], mass);
      st.position[i] = glm::vec4(glm::vec3(head.apply(glm::dvec3(groom.points[i]))), 1.0f);
    }
  }
  return st;
}

}  // namespace csm
