#include "sim/groom/fit.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include "sim/head/distance_grid.h"

namespace csm::io {
namespace {

using DVec = glm::dvec3;

struct Ball {
  DVec c{0.0};
  double r2 = -1.0;  // negative: empty
};

// Points are normalised to about unit size before the search, so an absolute tolerance
// is meaningful: it absorbs the rounding of the circumcentre formulas.
constexpr double kInsideEps = 1e-10;

bool inside(const Ball& b, const DVec& p) {
  const DVec d = p - b.c;
  return glm::dot(d, d) <= b.r2 + kInsideEps;
}

Ball ball2(const DVec& a, const DVec& b) {
  const DVec c = 0.5 * (a + b);
  const DVec d = a - c;
  return {c, glm::dot(d, d)};
}

Ball ball3(const DVec& p0, const DVec& p1, const DVec& p2) {
  const DVec a = p1 - p0, b = p2 - p0;
  const DVec n = glm::cross(a, b);
  const double denom = 2.0 * glm::dot(n, n);
  const double scale = glm::dot(a, a) * glm::dot(b, b);
  if (denom <= 1e-14 * scale) {
    // Collinear: the two farthest apart span the ball.
    Ball best = ball2(p0, p1);
    for (const Ball& cand : {ball2(p0, p2), ball2(p1, p2)}) {
      if (cand.r2 > best.r2) best = cand;
    }
    return best;
  }
  // Circumcentre of the triangle, in its plane.
  const DVec offset =
      (glm::dot(a, a) * glm::cross(b, n) + glm::dot(b, b) * glm::cross(n, a)) / denom;
  return {p0 + offset, glm::dot(offset, offset)};
}

Ball ball4(const DVec& p0, const DVec& p1, const DVec& p2, const DVec& p3) {
  const DVec a = p1 - p0, b = p2 - p0, c = p3 - p0;
  const double det = glm::dot(a, glm::cross(b, c));
  const double scale = glm::length(a) * glm::length(b) * glm::length(c);
  if (std::abs(det) > 1e-12 * scale) {
    // Circumsphere: the centre x (relative to p0) solves 2 v.x = |v|^2 for v in {a, b, c}.
    const DVec x = (glm::dot(a, a) * glm::cross(b, c) + glm::dot(b, b) * glm::cross(c, a) +
                    glm::dot(c, c) * glm::cross(a, b)) /
                   (2.0 * det);
    return {p0 + x, glm::dot(x, x)};
  }
  // Coplanar: the smallest ball through a subset that holds all four.
  const DVec p[4] = {p0, p1, p2, p3};
  Ball best;
  auto consider = [&](const Ball& cand) {
    for (const DVec& q : p) {
      if (!inside(cand, q)) return;
    }
    if (best.r2 < 0 || cand.r2 < best.r2) best = cand;
  };
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      consider(ball2(p[i], p[j]));
      for (int k = j + 1; k < 4; ++k) consider(ball3(p[i], p[j], p[k]));
    }
  }
  return best;
}

glm::mat3 rotationXyz(const glm::vec3& degrees) {
  const glm::vec3 r = glm::radians(degrees);
  const float cx = std::cos(r.x), sx = std::sin(r.x);
  const float cy = std::cos(r.y), sy = std::sin(r.y);
  const float cz = std::cos(r.z), sz = std::sin(r.z);
  // glm matrices are column-major: mat3(col0, col1, col2).
  const glm::mat3 rx({1, 0, 0}, {0, cx, sx}, {0, -sx, cx});
  const glm::mat3 ry({cy, 0, -sy}, {0, 1, 0}, {sy, 0, cy});
  const glm::mat3 rz({cz, sz, 0}, {-sz, cz, 0}, {0, 0, 1});
  return rz * ry * rx;
}

}  // namespace

Sphere boundingSphere(const std::vector<glm::vec3>& points) {
  if (points.empty()) return {glm::vec3(0.0f), 0.0f};
  // Normalise to unit size around the centroid so tolerances are scale-free.
  DVec lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
  for (const glm::vec3& p : points) {
    lo = glm::min(lo, DVec(p));
    hi = glm::max(hi, DVec(p));
  }
  const DVec mid = 0.5 * (lo + hi);
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (extent <= 0) return {glm::vec3(mid), 0.0f};
  std::vector<DVec> p(points.size());
  for (size_t i = 0; i < points.size(); ++i) p[i] = (DVec(points[i]) - mid) / extent;
  // Welzl's algorithm runs in expected linear time on randomly ordered input; a fixed LCG
  // keeps the order (and so the rounding) the same on every platform.
  uint64_t state = 0x9E3779B97F4A7C15ull;
  for (size_t i = p.size(); i > 1; --i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    std::swap(p[i - 1], p[(state >> 33) % i]);
  }
  Ball b{p[0], 0.0};
  for (size_t i = 1; i < p.size(); ++i) {
    if (inside(b, p[i])) continue;
    b = {p[i], 0.0};
    for (size_t j = 0; j < i; ++j) {
      if (inside(b, p[j])) continue;
      b = ball2(p[i], p[j]);
      for (size_t k = 0; k < j; ++k) {
        if (inside(b, p[k])) continue;
        b = ball3(p[i], p[j], p[k]);
        for (size_t l = 0; l < k; ++l) {
          if (!inside(b, p[l])) b = ball4(p[i], p[j], p[k], p[l]);
        }
      }
    }
  }
  return {glm::vec3(mid + b.c * extent), static_cast<float>(std::sqrt(b.r2) * extent)};
}

FitReport fitToHead(Groom& groom, const FitOptions& options) {
  FitReport report;
  const std::vector<Sphere> fallbackHead = {{glm::vec3(0.0f), 0.1f}};
  const std::vector<Sphere>& spheres =
      options.headSpheres.empty() ? fallbackHead : options.headSpheres;
  const Sphere& head =
      *std::max_element(spheres.begin(), spheres.end(),
                        [](const Sphere& a, const Sphere& b) { return a.radius < b.radius; });

  const glm::mat3 rotation = rotationXyz(options.rotationDeg);
  float scale = options.scale > 0.0f ? options.scale : 1.0f;
  glm::vec3 translation(0.0f);
  if (options.autoFit && groom.strandCount() > 0) {
    std::vector<glm::vec3> roots(groom.strandCount());
    for (size_t s = 0; s < roots.size(); ++s) roots[s] = rotation * groom.points[groom.first[s]];
    const Sphere bound = boundingSphere(roots);
    report.rootBoundingRadius = bound.radius;
    if (options.scale <= 0.0f && bound.radius > 0.0f) scale = head.radius / bound.radius;
    // For a scalp-shaped root set (a cap of a sphere reaching at least its equator) the
    // bounding sphere is the scalp's own sphere, so this lands the roots on the head with
    // their centroid above its centre. Smaller caps end up inside and want snapRoots.
    translation = head.center - scale * bound.center;
  }
  translation += options.offset;
  report.scale = scale;
  report.rotation = rotation;
  report.translation = translation;

  for (glm::vec3& p : groom.points) p = scale * (rotation * p) + translation;
  for (float& t : groom.thickness) t *= scale;
  for (Groom::FollowHairs& f : groom.follow) f.radius *= scale;

  if (options.snapRoots && options.headField) {
    // The nearest point of the field's surface.
    for (size_t s = 0; s < groom.strandCount(); ++s) {
      const glm::vec3 root = groom.points[groom.first[s]];
      const glm::vec3 move =
          glm::vec3(projectToSurface(*options.headField, glm::dvec3(root))) - root;
      const float distance = glm::length(move);
      if (distance == 0.0f) continue;
      for (uint32_t i = groom.first[s]; i < groom.first[s + 1]; ++i) groom.points[i] += move;
      ++report.snappedStrands;
      report.maxSnapDistance = std::max(report.maxSnapDistance, distance);
    }
  } else if (options.snapRoots) {
    for (size_t s = 0; s < groom.strandCount(); ++s) {
      const glm::vec3 root = groom.points[groom.first[s]];
      // The nearest surface point that is not buried in another sphere (a root snapped
      // onto the head sphere where the neck sphere overlaps it would start in collision).
      glm::vec3 best = root;
      float bestGap = std::numeric_limits<float>::max();
      bool bestBuried = true;
      for (const Sphere& sphere : spheres) {
        glm::vec3 normal = root - sphere.center;
        const float len = glm::length(normal);
        // A root at the very centre has no normal; up is as good as any and matches y-up.
        normal = len > 0.0f ? normal / len : glm::vec3(0.0f, 1.0f, 0.0f);
        const glm::vec3 onSurface = sphere.center + sphere.radius * normal;
        bool buried = false;
        for (const Sphere& other : spheres) {
          if (&other != &sphere && glm::length(onSurface - other.center) < other.radius * 0.999f) {
            buried = true;
          }
        }
        const float gap = std::abs(len - sphere.radius);
        if ((bestBuried && !buried) || (buried == bestBuried && gap < bestGap)) {
          best = onSurface, bestGap = gap, bestBuried = buried;
        }
      }
      const glm::vec3 move = best - root;
      const float distance = glm::length(move);
      if (distance == 0.0f) continue;
      for (uint32_t i = groom.first[s]; i < groom.first[s + 1]; ++i) groom.points[i] += move;
      ++report.snappedStrands;
      report.maxSnapDistance = std::max(report.maxSnapDistance, distance);
    }
  }
  return report;
}

}  // namespace csm::io
