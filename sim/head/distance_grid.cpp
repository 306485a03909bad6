#include "sim/head/distance_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "sim/base/parallel.h"

namespace csm {

double DistanceGrid::sample(const glm::dvec3& p, glm::dvec3* gradient) const {
  if (!std::isfinite(p.x + p.y + p.z)) {
    // No cell to read (floor(NaN) has no integer; a groom scaled past float's range, a state
    // gone bad): not a distance either.
    if (gradient) *gradient = glm::dvec3(0.0);
    return std::numeric_limits<double>::quiet_NaN();
  }
  const glm::dvec3 f = (p - glm::dvec3(origin)) / double(cell);
  const glm::dvec3 top = glm::dvec3(dims - 1);
  const glm::dvec3 inside = glm::clamp(f, glm::dvec3(0.0), top);
  // Beyond the border: the border's distance plus the way to it (the border lies outside the
  // shape, so this stays positive and grows away from it).
  const double beyond = glm::length(f - inside) * double(cell);
  const glm::ivec3 c = glm::min(glm::ivec3(glm::floor(inside)), dims - 2);
  const glm::dvec3 t = inside - glm::dvec3(c);
  glm::dvec4 v(0.0);
  for (int corner = 0; corner < 8; ++corner) {
    const int dx = corner & 1, dy = (corner >> 1) & 1, dz = corner >> 2;
    const double w = (dx ? t.x : 1.0 - t.x) * (dy ? t.y : 1.0 - t.y) * (dz ? t.z : 1.0 - t.z);
    v += w * glm::dvec4(nodes[index(c.x + dx, c.y + dy, c.z + dz)]);
  }
  if (gradient) *gradient = glm::dvec3(v);
  return v.w + beyond;
}

DistanceGrid sampleDistance(const DistanceFunction& f, const glm::dvec3& lo, const glm::dvec3& hi,
                            double cell) {
  DistanceGrid g;
  g.origin = glm::vec3(lo);
  g.cell = float(cell);
  g.dims = glm::max(glm::ivec3(glm::ceil((hi - lo) / cell)) + 1, glm::ivec3(2));
  g.nodes.resize(size_t(g.dims.x) * g.dims.y * g.dims.z);
  const double e = 0.25 * cell;
  parallelFor(size_t(g.dims.z), 1, [&](size_t k0, size_t k1) {
    for (size_t k = k0; k < k1; ++k)
      for (int j = 0; j < g.dims.y; ++j)
        for (int i = 0; i < g.dims.x; ++i) {
          const glm::dvec3 p = lo + cell * glm::dvec3(i, j, double(k));
          const glm::dvec3 grad(f(p + glm::dvec3(e, 0, 0)) - f(p - glm::dvec3(e, 0, 0)),
                                f(p + glm::dvec3(0, e, 0)) - f(p - glm::dvec3(0, e, 0)),
                                f(p + glm::dvec3(0, 0, e)) - f(p - glm::dvec3(0, 0, e)));
          g.nodes[g.index(i, j, int(k))] = glm::vec4(glm::vec3(grad / (2.0 * e)), float(f(p)));
        }
  });
  return g;
}

bool PosedField::contains(const glm::dvec3& world) const {
  return grid && grid->sample(glm::inverse(pose.rotation) * (world - pose.translation)) < 0.0;
}

bool pushOutOfField(const DistanceGrid& g, glm::dvec3& p, double radius, glm::dvec3* normal,
                    double* distance) {
  glm::dvec3 grad;
  double d = g.sample(p, &grad);
  if (distance) *distance = d;
  if (!(d < radius)) return false;  // outside, or not finite
  // The field is close to a distance, not exactly one (smooth unions, interpolation): a
  // second step takes what the first left.
  for (int step = 0; step < 2 && d < radius; ++step) {
    const double len = glm::length(grad);
    const glm::dvec3 n = len > 1e-12 ? grad / len : glm::dvec3(0.0, 1.0, 0.0);
    p += (radius - d) * n;
    if (normal) *normal = n;
    d = g.sample(p, &grad);
  }
  if (distance) *distance = d;
  return true;
}

glm::dvec3 projectToSurface(const DistanceGrid& g, glm::dvec3 p) {
  for (int step = 0; step < 4; ++step) {
    glm::dvec3 grad;
    const double d = g.sample(p, &grad);
    const double len2 = glm::dot(grad, grad);
    if (len2 < 1e-12) break;
    p -= d * grad / len2;
  }
  return p;
}

glm::dvec3 surfaceAlong(const DistanceGrid& g, const glm::dvec3& from, const glm::dvec3& dir) {
  // March inwards from where the ray leaves the grid's box: the first zero met is the
  // outermost surface. Inside the box the field is close to a distance; beyond it, only a
  // bound from above, which a march could step over a surface with.
  const glm::dvec3 lo(g.origin), hi = lo + glm::dvec3(g.dims - 1) * double(g.cell);
  double far = 1e300;
  for (int a = 0; a < 3; ++a)
    if (std::abs(dir[a]) > 1e-12)
      far = std::min(far, ((dir[a] > 0.0 ? hi[a] : lo[a]) - from[a]) / dir[a]);
  if (!(far > 0.0 && far < 1e300)) return from;
  double t = far;
  for (int step = 0; step < 1024; ++step) {
    const double d = g.sample(from + t * dir);
    if (d < 1e-5) break;
    t -= std::max(0.9 * d, 1e-4);
    if (t <= 0.0) return from;
  }
  // Bisect between a point outside and one inside (the march stops just short of the surface).
  double inside = t;
  for (int step = 0; step < 1000 && g.sample(from + inside * dir) >= 0.0 && inside > 0.0; ++step)
    inside -= 1e-5;
  double outside = inside + 1e-4;
  while (g.sample(from + outside * dir) < 0.0 && outside < far) outside += 1e-3;
  for (int step = 0; step < 40; ++step) {
    const double mid = 0.5 * (outside + inside);
    (g.sample(from + mid * dir) < 0.0 ? inside : outside) = mid;
  }
  return from + outside * dir;
}

}  // namespace csm
