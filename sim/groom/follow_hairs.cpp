#include "sim/groom/follow_hairs.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "sim/base/random.h"
#include "sim/base/shortest_turn.h"

namespace csm {

namespace {

// Any unit vector across `t`.
glm::dvec3 across(const glm::dvec3& t) {
  const glm::dvec3 other = std::abs(t.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return glm::normalize(glm::cross(t, other));
}

// Strand s's follow hair k: its guide displaced as addFollowHairs says.
std::vector<glm::vec3> followHair(const Groom& g, size_t s, uint32_t k, const GrowthHead& head,
                                  double margin, uint64_t seed) {
  const Groom::FollowHairs& f = g.follow[s];
  const uint32_t begin = g.first[s], end = g.first[s + 1];
  std::vector<double> share(end - begin, 0.0);
  for (uint32_t i = begin + 1; i < end; ++i)
    share[i - begin] = share[i - begin - 1] + double(glm::length(g.points[i] - g.points[i - 1]));
  const double length = share.back() > 0.0 ? share.back() : 1.0;
  // A root spread evenly over the disc: the radius by the square root of a uniform number.
  glm::dvec3 tangent = glm::normalize(glm::dvec3(g.points[begin + 1] - g.points[begin]));
  const glm::dvec3 u = across(tangent), v = glm::cross(tangent, u);
  const double angle = 2.0 * glm::pi<double>() * random01(seed, s, 2 * uint64_t(k));
  const double radius = double(f.radius) * std::sqrt(random01(seed, s, 2 * uint64_t(k) + 1));
  glm::dvec3 offset = radius * (std::cos(angle) * u + std::sin(angle) * v);
  std::vector<glm::vec3> out(end - begin);
  for (uint32_t i = begin; i < end; ++i) {
    if (i > begin && i + 1 < end) {
      // Turned as the strand turns at this point, so the offset stays across it (not at a
      // hairpin: no one shortest turn).
      const glm::dvec3 next = glm::dvec3(g.points[i + 1] - g.points[i]);
      if (glm::length(next) > 0.0) {
        const glm::dvec3 turned = glm::normalize(next);
        offset = shortestTurn(tangent, turned) * offset;
        tangent = turned;
      }
    }
    const double grow = 1.0 + double(f.tipSeparation) * share[i - begin] / length;
    glm::dvec3 p = glm::dvec3(g.points[i]) + grow * offset;
    glm::dvec3 normal;
    if (i == begin) {
      p -= head.distance(p, normal) * normal;
    } else {
      for (int pass = 0; pass < 8 && head.pushOut(p, margin); ++pass) {
      }
    }
    out[i - begin] = glm::vec3(p);
  }
  return out;
}

}  // namespace

std::vector<uint32_t> addFollowHairs(Groom& g, const GrowthHead& head, double margin,
                                     uint64_t seed) {
  if (g.follow.empty()) return {};
  const size_t guides = g.strandCount();
  std::vector<uint32_t> guideStrands(guides);
  for (size_t s = 0; s < guides; ++s) guideStrands[s] = uint32_t(s);
  for (size_t s = 0; s < guides; ++s)
    for (uint32_t k = 0; k < g.follow[s].count; ++k) {
      g.addStrand(followHair(g, s, k, head, margin, seed));
      g.addStrandData(g, s);
    }
  g.follow.clear();
  return guideStrands;
}

}  // namespace csm
