#include "sim/head/mesh_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "sim/base/parallel.h"

namespace csm {

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

}  // namespace csm
