#include "sim/head/surface_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace csm {

namespace {

// The Kuhn (Freudenthal) split of a cube into six tetrahedra about the diagonal 0-7: corner
// c is (c & 1, c >> 1 & 1, c >> 2), and every tetrahedron is a path 0 -> 7 along the axes.
constexpr std::array<std::array<int, 4>, 6> kTetrahedra{
    {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};

// p moved onto the zero level of f by Newton's steps along its gradient; n its normal there.
void projectOnto(const DistanceFunction& f, glm::dvec3& p, glm::dvec3& n) {
  for (int step = 0; step < 3; ++step) {
    const double e = 1e-5, d = f(p);
    const glm::dvec3 grad(f(p + glm::dvec3(e, 0, 0)) - f(p - glm::dvec3(e, 0, 0)),
                          f(p + glm::dvec3(0, e, 0)) - f(p - glm::dvec3(0, e, 0)),
                          f(p + glm::dvec3(0, 0, e)) - f(p - glm::dvec3(0, 0, e)));
    n = grad / (2.0 * e);
    const double len2 = glm::dot(n, n);
    if (len2 < 1e-12) break;
    p -= d * n / len2;
  }
}

bool folded(const SurfaceMesh& m, size_t t) {
  const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                  c = m.positions[m.indices[t + 2]];
  const glm::vec3 n =
      m.normals[m.indices[t]] + m.normals[m.indices[t + 1]] + m.normals[m.indices[t + 2]];
  return glm::dot(glm::cross(b - a, c - a), n) < 0.0f;
}

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
      if (exact) projectOnto(exact, p, n);
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

size_t foldedTriangles(const SurfaceMesh& m) {
  size_t count = 0;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3) count += folded(m, t);
  return count;
}

size_t relaxFolds(SurfaceMesh& m, const DistanceFunction& exact, int rounds) {
  std::vector<std::vector<uint32_t>> neighbours(m.positions.size());
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = m.indices[t + k], b = m.indices[t + (k + 1) % 3];
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
  std::vector<char> moving(m.positions.size());
  size_t left = foldedTriangles(m);
  for (int round = 0; round < rounds && left > 0; ++round) {
    std::fill(moving.begin(), moving.end(), 0);
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3)
      if (folded(m, t))
        for (int k = 0; k < 3; ++k) {
          const uint32_t v = m.indices[t + k];
          moving[v] = 1;
          for (uint32_t w : neighbours[v]) moving[w] = 1;
        }
    // Every moved vertex from its neighbours' places before this round, so that the result does
    // not depend on the order the vertices are taken in.
    const std::vector<glm::vec3> before = m.positions;
    for (size_t v = 0; v < m.positions.size(); ++v) {
      if (!moving[v] || neighbours[v].empty()) continue;
      glm::dvec3 mean(0.0);
      for (uint32_t w : neighbours[v]) mean += glm::dvec3(before[w]);
      glm::dvec3 p = mean / double(neighbours[v].size()), n(m.normals[v]);
      projectOnto(exact, p, n);
      m.positions[v] = glm::vec3(p);
      if (glm::length(n) > 1e-12) m.normals[v] = glm::vec3(glm::normalize(n));
    }
    left = foldedTriangles(m);
  }
  return left;
}

SurfaceMesh coarserMesh(const SurfaceMesh& m, size_t triangles) {
  const size_t have = m.indices.size() / 3;
  if (have <= triangles || triangles == 0 || m.positions.empty()) return m;
  double edges = 0.0;
  for (size_t t = 0; t < have; ++t)
    for (int k = 0; k < 3; ++k)
      edges += glm::length(m.positions[m.indices[3 * t + k]] -
                           m.positions[m.indices[3 * t + (k + 1) % 3]]);
  const double meanEdge = edges / double(3 * have);
  // Triangles go with the square of the edge: cells that much larger than an edge.
  const double cell = meanEdge * std::sqrt(double(have) / double(triangles));
  if (!(cell > 0.0)) return m;
  struct Cluster {
    glm::dvec3 position{0.0}, normal{0.0};
    int count = 0;
  };
  std::unordered_map<uint64_t, uint32_t> clusterOf;
  std::vector<Cluster> clusters;
  std::vector<uint32_t> remap(m.positions.size());
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const glm::dvec3 p(m.positions[i]);
    auto key = [&](double v) { return uint64_t(int64_t(std::floor(v / cell)) & 0x1fffff); };
    const uint64_t k = key(p.x) | key(p.y) << 21 | key(p.z) << 42;
    auto [it, added] = clusterOf.try_emplace(k, uint32_t(clusters.size()));
    if (added) clusters.emplace_back();
    Cluster& c = clusters[it->second];
    c.position += p;
    if (i < m.normals.size()) c.normal += glm::dvec3(m.normals[i]);
    ++c.count;
    remap[i] = it->second;
  }
  SurfaceMesh out;
  out.positions.reserve(clusters.size());
  out.normals.reserve(clusters.size());
  for (const Cluster& c : clusters) {
    out.positions.emplace_back(c.position / double(c.count));
    const double n = glm::length(c.normal);
    out.normals.emplace_back(n > 0.0 ? c.normal / n : glm::dvec3(0.0, 1.0, 0.0));
  }
  for (size_t t = 0; t < have; ++t) {
    const uint32_t a = remap[m.indices[3 * t]], b = remap[m.indices[3 * t + 1]],
                   c = remap[m.indices[3 * t + 2]];
    if (a != b && b != c && a != c) out.indices.insert(out.indices.end(), {a, b, c});
  }
  return out;
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

size_t capHoles(SurfaceMesh& m, std::vector<glm::vec3>* centres) {
  const uint64_t n = m.positions.size();
  std::unordered_map<uint64_t, int> directed;
  for (size_t t = 0; t + 2 < m.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) ++directed[m.indices[t + e] * n + m.indices[t + (e + 1) % 3]];
  // Each boundary vertex's one boundary edge out of it.
  std::unordered_map<uint32_t, uint32_t> next;
  std::vector<uint32_t> starts;
  for (const auto& [key, count] : directed) {
    const uint32_t a = uint32_t(key / n), b = uint32_t(key % n);
    if (count != 1 || directed.count(uint64_t(b) * n + a)) continue;
    if (!next.emplace(a, b).second) return 0;  // two loops meet at a: not simple
    starts.push_back(a);
  }
  if (next.empty()) return 0;
  std::sort(starts.begin(), starts.end());  // the same caps whatever the map's order
  std::vector<std::vector<uint32_t>> loops;
  std::unordered_map<uint32_t, bool> seen;
  for (const uint32_t start : starts) {
    if (seen[start]) continue;
    std::vector<uint32_t> loop;
    uint32_t v = start;
    while (!seen[v]) {
      seen[v] = true;
      loop.push_back(v);
      auto it = next.find(v);
      if (it == next.end()) return 0;  // the boundary stops: not a loop
      v = it->second;
    }
    if (v != start || loop.size() < 3) return 0;
    loops.push_back(std::move(loop));
  }
  for (const std::vector<uint32_t>& loop : loops) {
    glm::dvec3 mean(0.0), normal(0.0);
    for (const uint32_t v : loop) mean += glm::dvec3(m.positions[v]);
    mean /= double(loop.size());
    const auto c = uint32_t(m.positions.size());
    m.positions.emplace_back(mean);
    if (centres) centres->emplace_back(mean);
    if (!m.normals.empty()) m.normals.emplace_back(0.0f, 1.0f, 0.0f);
    for (size_t k = 0; k < loop.size(); ++k) {
      const uint32_t a = loop[k], b = loop[(k + 1) % loop.size()];
      m.indices.insert(m.indices.end(), {b, a, c});  // b->a against the face's a->b
    }
  }
  return loops.size();
}

}  // namespace csm
