#include "sim/head_shape.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "sim/hairstyle.h"
#include "sim/io/obj_mesh.h"
#include "sim/parallel.h"

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

namespace {

double sphere(const glm::dvec3& p, const glm::dvec3& c, double r) {
  return glm::length(p - c) - r;
}

// Inigo Quilez's ellipsoid bound: exact on the surface, close to the distance near it.
double ellipsoid(const glm::dvec3& p, const glm::dvec3& c, const glm::dvec3& r) {
  const glm::dvec3 q = p - c;
  const double k0 = glm::length(q / r);
  const double k1 = glm::length(q / (r * r));
  return k1 > 1e-12 ? k0 * (k0 - 1.0) / k1 : -std::min(r.x, std::min(r.y, r.z));
}

double capsule(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, double r) {
  const glm::dvec3 pa = p - a, ba = b - a;
  const double h = std::clamp(glm::dot(pa, ba) / glm::dot(ba, ba), 0.0, 1.0);
  return glm::length(pa - ba * h) - r;
}

// Polynomial smooth minimum: the union of two shapes with a fillet of about k.
double smoothUnion(double a, double b, double k) {
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

double smoothSubtract(double a, double cut, double k) {
  return -smoothUnion(-a, cut, k);
}

}  // namespace

double mannequinDistance(const glm::dvec3& q) {
  // Left-right symmetric: model the right half (x >= 0) and mirror.
  const glm::dvec3 p(std::abs(q.x), q.y, q.z);
  // Cranium and the face's mass below the forehead.
  double d = ellipsoid(p, {0.0, 0.005, -0.012}, {0.074, 0.095, 0.094});
  d = smoothUnion(d, ellipsoid(p, {0.0, -0.045, 0.025}, {0.060, 0.075, 0.060}), 0.03);
  // Jaw and chin.
  d = smoothUnion(d, ellipsoid(p, {0.0, -0.083, 0.034}, {0.050, 0.040, 0.054}), 0.025);
  d = smoothUnion(d, sphere(p, {0.0, -0.110, 0.068}, 0.019), 0.02);
  // Cheekbones and brow ridge.
  d = smoothUnion(d, sphere(p, {0.043, -0.030, 0.058}, 0.022), 0.02);
  d = smoothUnion(d, capsule(p, {0.0, 0.004, 0.076}, {0.040, 0.004, 0.072}, 0.012), 0.015);
  // Eye sockets, each with its eye.
  d = smoothSubtract(d, sphere(p, {0.032, -0.013, 0.091}, 0.017), 0.008);
  d = smoothUnion(d, sphere(p, {0.032, -0.014, 0.070}, 0.0125), 0.004);
  // Nose: bridge, tip and wings.
  d = smoothUnion(d, capsule(p, {0.0, -0.004, 0.086}, {0.0, -0.043, 0.103}, 0.008), 0.012);
  d = smoothUnion(d, sphere(p, {0.0, -0.046, 0.100}, 0.011), 0.008);
  d = smoothUnion(d, sphere(p, {0.012, -0.051, 0.091}, 0.008), 0.008);
  // Lips.
  d = smoothUnion(d, capsule(p, {0.0, -0.071, 0.086}, {0.019, -0.073, 0.080}, 0.0065), 0.008);
  d = smoothUnion(d, capsule(p, {0.0, -0.083, 0.083}, {0.016, -0.082, 0.078}, 0.006), 0.008);
  // Ears.
  d = smoothUnion(d, ellipsoid(p, {0.074, -0.025, -0.010}, {0.011, 0.030, 0.019}), 0.008);
  // Neck and shoulders.
  d = smoothUnion(d, capsule(p, {0.0, -0.070, -0.020}, {0.0, -0.250, -0.025}, 0.055), 0.03);
  d = smoothUnion(d, ellipsoid(p, {0.0, -0.305, -0.015}, {0.190, 0.075, 0.095}), 0.06);
  return d;
}

const DistanceGrid& mannequinGrid() {
  static const DistanceGrid grid =
      sampleDistance(mannequinDistance, {-0.215, -0.415, -0.125}, {0.215, 0.115, 0.135}, 0.004);
  return grid;
}

std::string headMeshPath(const Config& c) {
  return resolveRelative(c.head.meshDir, c.head.mesh);
}

const LoadedHead* loadHeadMesh(const std::string& path, std::string* error) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<const LoadedHead>> loaded;
  std::lock_guard lock(mutex);
  if (auto it = loaded.find(path); it != loaded.end()) return it->second.get();
  io::ObjReadResult read = io::readObjMesh(path);
  if (!read.mesh) {
    if (error) *error = read.error;
    return nullptr;
  }
  auto head = std::make_unique<LoadedHead>();
  head->mesh = std::move(*read.mesh);
  head->grid = meshDistanceGrid(head->mesh, 0.004, 0.02);
  return (loaded[path] = std::move(head)).get();
}

namespace {

// The OBJ head.mesh names, or null for the mannequin (and for a file gone since the scene was
// checked). Presets and --set are checked (crossCheck) before a scene runs, so this finds it
// loaded.
const LoadedHead* meshHead(const Config& c) {
  return c.head.mesh.empty() ? nullptr : loadHeadMesh(headMeshPath(c), nullptr);
}

}  // namespace

const DistanceGrid& headShapeField(const Config& c) {
  const LoadedHead* head = meshHead(c);
  return head ? head->grid : mannequinGrid();
}

const DistanceGrid* headField(const Config& c) {
  if (c.collision.headShape != HeadShape::Sdf) return nullptr;
  return &headShapeField(c);
}

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

const std::vector<Sphere>& headSpheres(const Config& c) {
  if (!c.head.fitSpheres) return c.head.spheres;
  static std::mutex mutex;
  static std::map<std::pair<const DistanceGrid*, int>, std::vector<Sphere>> fitted;
  const DistanceGrid& g = headShapeField(c);
  const int count = int(c.head.spheres.size());
  std::lock_guard lock(mutex);
  auto [it, added] = fitted.try_emplace({&g, count});
  if (added) it->second = fitSpheres(g, count);
  return it->second;
}

const SurfaceMesh* headSurface(const Config& c) {
  if (c.collision.headShape != HeadShape::Sdf) return nullptr;
  const LoadedHead* head = meshHead(c);
  return head ? &head->mesh : &mannequinMesh();
}

namespace {

// The point of triangle abc nearest to p (Ericson, Real-Time Collision Detection, 5.1.5).
glm::dvec3 nearestOnTriangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                             const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace

DistanceGrid meshDistanceGrid(const SurfaceMesh& m, double cell, double margin) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::vec3& p : m.positions) {
    lo = glm::min(lo, glm::dvec3(p));
    hi = glm::max(hi, glm::dvec3(p));
  }
  lo -= margin;
  hi += margin;
  DistanceGrid g;
  g.origin = glm::vec3(lo);
  g.cell = float(cell);
  g.dims = glm::max(glm::ivec3(glm::ceil((hi - lo) / cell)) + 1, glm::ivec3(2));
  const size_t count = size_t(g.dims.x) * g.dims.y * g.dims.z;
  const size_t triangles = m.indices.size() / 3;
  auto corner = [&](size_t t, int c) { return glm::dvec3(m.positions[m.indices[3 * t + c]]); };
  auto node = [&](int i, int j, int k) {
    return glm::dvec3(g.origin) + cell * glm::dvec3(i, j, k);
  };
  auto distanceTo = [&](const glm::dvec3& p, size_t t) {
    return glm::length(p - nearestOnTriangle(p, corner(t, 0), corner(t, 1), corner(t, 2)));
  };
  std::vector<double> dist(count, std::numeric_limits<double>::infinity());
  std::vector<int32_t> nearest(count, -1);

  // Exact distances within two cells of each triangle, a slice of nodes per task; triangles
  // are listed by the slices they reach.
  const double band = 2.0 * cell;
  std::vector<std::vector<uint32_t>> bySlice(size_t(g.dims.z));
  std::vector<glm::ivec3> tLo(triangles), tHi(triangles);
  for (size_t t = 0; t < triangles; ++t) {
    glm::dvec3 a = corner(t, 0), b = a;
    for (int c = 1; c < 3; ++c) {
      a = glm::min(a, corner(t, c));
      b = glm::max(b, corner(t, c));
    }
    tLo[t] = glm::max(glm::ivec3(glm::floor((a - band - lo) / cell)), glm::ivec3(0));
    tHi[t] = glm::min(glm::ivec3(glm::ceil((b + band - lo) / cell)), g.dims - 1);
    for (int k = tLo[t].z; k <= tHi[t].z; ++k) bySlice[size_t(k)].push_back(uint32_t(t));
  }
  parallelFor(size_t(g.dims.z), 1, [&](size_t k0, size_t k1) {
    for (size_t k = k0; k < k1; ++k)
      for (uint32_t t : bySlice[k])
        for (int j = tLo[t].y; j <= tHi[t].y; ++j)
          for (int i = tLo[t].x; i <= tHi[t].x; ++i) {
            const size_t n = g.index(i, j, int(k));
            const double d = distanceTo(node(i, j, int(k)), t);
            if (d < dist[n]) {
              dist[n] = d;
              nearest[n] = int32_t(t);
            }
          }
  });

  // Beyond the band, each node takes the nearest of its neighbours' nearest triangles, in
  // sweeps along the eight diagonal directions (Tsai 2002, closest point propagation).
  for (int dir = 0; dir < 8; ++dir) {
    const int sx = dir & 1 ? -1 : 1, sy = dir & 2 ? -1 : 1, sz = dir & 4 ? -1 : 1;
    for (int kk = 0; kk < g.dims.z; ++kk) {
      const int k = sz > 0 ? kk : g.dims.z - 1 - kk;
      for (int jj = 0; jj < g.dims.y; ++jj) {
        const int j = sy > 0 ? jj : g.dims.y - 1 - jj;
        for (int ii = 0; ii < g.dims.x; ++ii) {
          const int i = sx > 0 ? ii : g.dims.x - 1 - ii;
          const size_t n = g.index(i, j, k);
          const glm::ivec3 from[3] = {{i - sx, j, k}, {i, j - sy, k}, {i, j, k - sz}};
          for (const glm::ivec3& f : from) {
            if (glm::any(glm::lessThan(f, glm::ivec3(0))) ||
                glm::any(glm::greaterThanEqual(f, g.dims)))
              continue;
            const int32_t t = nearest[g.index(f.x, f.y, f.z)];
            if (t < 0 || t == nearest[n]) continue;
            const double d = distanceTo(node(i, j, k), size_t(t));
            if (d < dist[n]) {
              dist[n] = d;
              nearest[n] = t;
            }
          }
        }
      }
    }
  }

  // Inside where a ray along +x from the box's side has crossed the surface an odd number of
  // times. The ray is moved off the node row by an odd fraction of a cell so that it does not
  // pass through the vertices and edges of meshes made on a regular grid.
  std::vector<std::vector<uint32_t>> byRow(size_t(g.dims.y) * g.dims.z);
  for (size_t t = 0; t < triangles; ++t)
    for (int k = std::max(tLo[t].z, 0); k <= tHi[t].z; ++k)
      for (int j = tLo[t].y; j <= tHi[t].y; ++j)
        byRow[size_t(j) + size_t(g.dims.y) * k].push_back(uint32_t(t));
  std::vector<uint8_t> inside(count, 0);
  parallelFor(byRow.size(), 16, [&](size_t r0, size_t r1) {
    std::vector<double> crossings;
    for (size_t r = r0; r < r1; ++r) {
      const int j = int(r % size_t(g.dims.y)), k = int(r / size_t(g.dims.y));
      const double y = lo.y + cell * j + 1.2345e-4 * cell, z = lo.z + cell * k + 2.3456e-4 * cell;
      crossings.clear();
      for (uint32_t t : byRow[r]) {
        const glm::dvec3 a = corner(t, 0), b = corner(t, 1), c = corner(t, 2);
        // Barycentric coordinates of (y, z) in the triangle's projection on the yz plane.
        const double det = (b.y - a.y) * (c.z - a.z) - (c.y - a.y) * (b.z - a.z);
        if (std::abs(det) < 1e-30) continue;
        const double u = ((y - a.y) * (c.z - a.z) - (c.y - a.y) * (z - a.z)) / det;
        const double v = ((b.y - a.y) * (z - a.z) - (y - a.y) * (b.z - a.z)) / det;
        if (u < 0.0 || v < 0.0 || u + v > 1.0) continue;
        crossings.push_back(a.x + u * (b.x - a.x) + v * (c.x - a.x));
      }
      std::sort(crossings.begin(), crossings.end());
      size_t passed = 0;
      for (int i = 0; i < g.dims.x; ++i) {
        const double x = lo.x + cell * i;
        while (passed < crossings.size() && crossings[passed] < x) ++passed;
        inside[g.index(i, j, k)] = passed & 1;
      }
    }
  });

  g.nodes.resize(count);
  parallelFor(size_t(g.dims.z), 1, [&](size_t k0, size_t k1) {
    for (size_t k = k0; k < k1; ++k)
      for (int j = 0; j < g.dims.y; ++j)
        for (int i = 0; i < g.dims.x; ++i) {
          const size_t n = g.index(i, j, int(k));
          const double sign = inside[n] ? -1.0 : 1.0;
          const glm::dvec3 p = node(i, j, int(k));
          const size_t t = size_t(nearest[n]);
          const glm::dvec3 a = corner(t, 0), b = corner(t, 1), c = corner(t, 2);
          const glm::dvec3 away = p - nearestOnTriangle(p, a, b, c);
          const double len = glm::length(away);
          // At the surface (within what rounding and the ray's offset leave uncertain) the
          // direction away from it is the face's normal; a face with no area (three vertices
          // on a line, which a closed surface may hold) has none: its vertices' normals.
          const glm::dvec3 face = glm::cross(b - a, c - a);
          const double area = glm::length(face);
          glm::dvec3 grad = len > 1e-3 * cell ? sign * away / len : face / area;
          if (!(len > 1e-3 * cell) && !(area > 0.0)) {
            glm::dvec3 n(0.0);
            if (m.normals.size() == m.positions.size())
              for (int v = 0; v < 3; ++v) n += glm::dvec3(m.normals[m.indices[3 * t + v]]);
            const double nl = glm::length(n);
            grad = nl > 1e-12 ? n / nl : glm::dvec3(0.0, 1.0, 0.0);
          }
          g.nodes[n] = glm::vec4(glm::vec3(grad), float(sign * dist[n]));
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

namespace {

// The Kuhn (Freudenthal) split of a cube into six tetrahedra about the diagonal 0-7: corner
// c is (c & 1, c >> 1 & 1, c >> 2), and every tetrahedron is a path 0 -> 7 along the axes.
constexpr std::array<std::array<int, 4>, 6> kTetrahedra{
    {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};

}  // namespace

SurfaceMesh meshZeroLevel(const DistanceGrid& g, const DistanceFunction& exact) {
  SurfaceMesh m;
  std::unordered_map<uint64_t, uint32_t> edgeVertex;
  auto position = [&](size_t node) {
    const size_t i = node % size_t(g.dims.x), j = node / size_t(g.dims.x) % size_t(g.dims.y),
                 k = node / (size_t(g.dims.x) * size_t(g.dims.y));
    return glm::dvec3(g.origin) + double(g.cell) * glm::dvec3(double(i), double(j), double(k));
  };
  // One vertex per grid edge that the surface cuts, shared by every triangle through it.
  auto vertexOn = [&](size_t a, size_t b) {
    if (a > b) std::swap(a, b);
    const uint64_t key = uint64_t(a) * uint64_t(g.nodes.size()) + b;
    auto [it, added] = edgeVertex.try_emplace(key, uint32_t(m.positions.size()));
    if (added) {
      const double da = g.nodes[a].w, db = g.nodes[b].w;
      const double t = std::clamp(da / (da - db), 0.0, 1.0);
      glm::dvec3 p = glm::mix(position(a), position(b), t);
      glm::dvec3 n = glm::mix(glm::dvec3(g.nodes[a]), glm::dvec3(g.nodes[b]), t);
      if (exact) {
        for (int step = 0; step < 3; ++step) {
          const double e = 1e-5, d = exact(p);
          const glm::dvec3 grad(exact(p + glm::dvec3(e, 0, 0)) - exact(p - glm::dvec3(e, 0, 0)),
                                exact(p + glm::dvec3(0, e, 0)) - exact(p - glm::dvec3(0, e, 0)),
                                exact(p + glm::dvec3(0, 0, e)) - exact(p - glm::dvec3(0, 0, e)));
          n = grad / (2.0 * e);
          const double len2 = glm::dot(n, n);
          if (len2 < 1e-12) break;
          p -= d * n / len2;
        }
      }
      m.positions.emplace_back(p);
      m.normals.emplace_back(glm::length(n) > 1e-12 ? glm::normalize(n) : glm::dvec3(0, 1, 0));
    }
    return it->second;
  };
  // Oriented by the midpoints of the cut edges, which never coincide (the vertices may, where
  // the surface passes through a node), so every triangle turns outwards.
  using Edge = std::pair<size_t, size_t>;
  auto triangle = [&](Edge a, Edge b, Edge c, const glm::dvec3& outward) {
    auto mid = [&](Edge e) { return 0.5 * (position(e.first) + position(e.second)); };
    if (glm::dot(glm::cross(mid(b) - mid(a), mid(c) - mid(a)), outward) < 0.0) std::swap(b, c);
    m.indices.insert(m.indices.end(), {vertexOn(a.first, a.second), vertexOn(b.first, b.second),
                                       vertexOn(c.first, c.second)});
  };
  for (int k = 0; k + 1 < g.dims.z; ++k)
    for (int j = 0; j + 1 < g.dims.y; ++j)
      for (int i = 0; i + 1 < g.dims.x; ++i) {
        std::array<size_t, 8> node;
        int insideCorners = 0;
        for (int c = 0; c < 8; ++c) {
          node[c] = g.index(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2));
          insideCorners += g.nodes[node[c]].w < 0.0f;
        }
        if (insideCorners == 0 || insideCorners == 8) continue;
        for (const auto& tet : kTetrahedra) {
          std::array<size_t, 4> in{}, out{};
          int nIn = 0, nOut = 0;
          glm::dvec3 inSum(0.0), outSum(0.0);
          for (int v : tet) {
            const size_t n = node[v];
            if (g.nodes[n].w < 0.0f) {
              in[nIn++] = n;
              inSum += position(n);
            } else {
              out[nOut++] = n;
              outSum += position(n);
            }
          }
          if (nIn == 0 || nOut == 0) continue;
          const glm::dvec3 outward = outSum / double(nOut) - inSum / double(nIn);
          if (nIn == 1 || nOut == 1) {
            // One corner apart from the other three: a triangle around it.
            const size_t lone = nIn == 1 ? in[0] : out[0];
            const std::array<size_t, 4>& rest = nIn == 1 ? out : in;
            triangle({lone, rest[0]}, {lone, rest[1]}, {lone, rest[2]}, outward);
          } else {
            // Two and two: a quad through the four cut edges, as two triangles.
            const Edge a{in[0], out[0]}, b{in[0], out[1]}, c{in[1], out[1]}, d{in[1], out[0]};
            triangle(a, b, c, outward);
            triangle(a, c, d, outward);
          }
        }
      }
  return m;
}

const SurfaceMesh& mannequinMesh() {
  static const SurfaceMesh mesh = meshZeroLevel(mannequinGrid(), mannequinDistance);
  return mesh;
}

size_t openEdges(const SurfaceMesh& m) {
  std::unordered_map<uint64_t, int> directed;
  const uint64_t n = m.positions.size();
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e)
      ++directed[uint64_t(m.indices[t + e]) * n + m.indices[t + (e + 1) % 3]];
  size_t open = 0;
  for (const auto& [key, count] : directed) {
    const uint64_t reverse = (key % n) * n + key / n;
    auto it = directed.find(reverse);
    if (count != 1 || it == directed.end() || it->second != 1) ++open;
  }
  return open;
}

}  // namespace csm
