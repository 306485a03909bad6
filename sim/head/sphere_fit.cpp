#include "sim/head/sphere_fit.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace csm {

namespace {

// The radius of the ball about c inside the field's shape: -distance at c, shrunk while a point
// of its surface (64 directions) lies outside by more than a quarter cell; a field that is not
// an exact distance (the mannequin's smooth union of primitives) can overstate it.
double insideRadius(const DistanceGrid& g, const glm::dvec3& c) {
  double r = -g.sample(c);
  for (int pass = 0; pass < 4 && r > 0.0; ++pass) {
    double worst = -1e30;
    for (int i = 0; i < 64; ++i) {  // a Fibonacci spiral of directions
      const double y = 1.0 - (i + 0.5) / 32.0, a = i * 2.399963229728653;
      const double s = std::sqrt(1.0 - y * y);
      worst = std::max(worst, g.sample(c + r * glm::dvec3(s * std::cos(a), y, s * std::sin(a))));
    }
    if (worst <= 0.25 * g.cell) break;
    r -= worst;
  }
  return std::max(r, 0.0);
}

}  // namespace

std::vector<Sphere> fitSpheres(const DistanceGrid& g, int count) {
  std::vector<Sphere> out;
  if (g.empty() || count <= 0) return out;
  constexpr double kLowest = -0.2;  // below this the neck meets the shoulders
  const double cell = g.cell;
  // Candidate centres: the nodes' y and z on the plane x = 0, inside the shape.
  std::vector<glm::dvec4> candidates;  // centre, radius
  for (int k = 0; k < g.dims.z; ++k)
    for (int j = 0; j < g.dims.y; ++j) {
      const glm::dvec3 c(0.0, g.origin.y + j * cell, g.origin.z + k * cell);
      if (c.y <= kLowest || g.sample(c) >= 0.0) continue;
      const double r = insideRadius(g, c);
      if (r > 0.0) candidates.emplace_back(c, r);
    }
  if (candidates.empty()) return out;
  // Coverage is counted on every second node inside the shape.
  std::vector<glm::dvec3> points;
  for (int k = 0; k < g.dims.z; k += 2)
    for (int j = 0; j < g.dims.y; j += 2)
      for (int i = 0; i < g.dims.x; i += 2) {
        const glm::dvec3 p = glm::dvec3(g.origin) + cell * glm::dvec3(i, j, k);
        if (p.y > kLowest && g.nodes[g.index(i, j, k)].w < 0.0f) points.push_back(p);
      }
  std::vector<char> covered(points.size(), 0);
  for (int n = 0; n < count; ++n) {
    size_t best = 0;
    double bestScore = -1.0;
    for (size_t a = 0; a < candidates.size(); ++a) {
      const glm::dvec3 c(candidates[a]);
      const double r = candidates[a].w;
      double score = r;  // the first: the largest ball
      if (n > 0) {
        score = 0.0;
        for (size_t q = 0; q < points.size(); ++q) {
          const glm::dvec3 d = points[q] - c;
          if (!covered[q] && glm::dot(d, d) <= r * r) score += 1.0;
        }
      }
      if (score > bestScore) bestScore = score, best = a;
    }
    const glm::dvec3 c(candidates[best]);
    const double r = candidates[best].w;
    out.push_back(Sphere{glm::vec3(c), float(r)});
    for (size_t q = 0; q < points.size(); ++q) {
      const glm::dvec3 d = points[q] - c;
      if (glm::dot(d, d) <= r * r) covered[q] = 1;
    }
  }
  return out;
}

}  // namespace csm
