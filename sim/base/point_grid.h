// Points in a uniform grid of cubes, for "every point within r of p": the roots of a groom for
// the children's neighbours (render/strand_geometry.cpp), the guides' sampling and the
// followers' binding (sim/groom/guides.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace csm {

class PointGrid {
 public:
  PointGrid(std::vector<glm::vec3> points, float cell) : points_(std::move(points)), cell_(cell) {
    for (std::size_t i = 0; i < points_.size(); ++i) {
      const glm::ivec3 c = cellOf(points_[i]);
      auto [it, added] = cells_.try_emplace(key(c));
      if (added) occupied_.push_back(c);
      it->second.points.push_back(i);
    }
    std::sort(occupied_.begin(), occupied_.end(), [](const glm::ivec3& a, const glm::ivec3& b) {
      return std::make_tuple(a.z, a.y, a.x) < std::make_tuple(b.z, b.y, b.x);
    });
    for (std::size_t k = 0; k < occupied_.size(); ++k) cells_.at(key(occupied_[k])).index = k;
  }
  // f(j) for every point j within `radius` of p, in a fixed order: the cells by z, then y, then
  // x, each cell's points in the order given. A search wider than the grid has cells visits the
  // occupied ones, in the same order.
  template <class F>
  void within(const glm::vec3& p, float radius, F&& f) const {
    cellsNear(p, radius, [&](std::size_t, const std::vector<std::size_t>& list, float) {
      for (std::size_t j : list)
        if (glm::length(points_[j] - p) <= radius) f(j);
    });
  }
  // f(cell, points, distance) for every occupied cell of the box `radius` around p, in the
  // order `within` takes: the cell's index (0 .. cells() - 1, fixed for the grid), its points,
  // and how far p is from the cell's box (a lower bound of each point's distance).
  template <class F>
  void cellsNear(const glm::vec3& p, float radius, F&& f) const {
    const int reach = int(std::ceil(radius / cell_));
    const glm::ivec3 c = cellOf(p);
    auto visit = [&](const Cell& cell, const glm::ivec3& at) {
      const glm::vec3 lo = glm::vec3(at) * cell_;
      const glm::vec3 d = glm::max(glm::max(lo - p, p - (lo + cell_)), glm::vec3(0.0f));
      f(cell.index, cell.points, glm::length(d));
    };
    const std::size_t side = std::size_t(2 * reach + 1);
    if (side * side * side > occupied_.size()) {
      for (const glm::ivec3& o : occupied_)
        if (glm::all(glm::lessThanEqual(glm::abs(o - c), glm::ivec3(reach))))
          visit(cells_.at(key(o)), o);
      return;
    }
    for (int z = -reach; z <= reach; ++z)
      for (int y = -reach; y <= reach; ++y)
        for (int x = -reach; x <= reach; ++x) {
          const glm::ivec3 at = c + glm::ivec3(x, y, z);
          const auto it = cells_.find(key(at));
          if (it != cells_.end()) visit(it->second, at);
        }
  }
  std::size_t cells() const { return occupied_.size(); }

 private:
  struct Cell {
    std::size_t index = 0;            // in occupied_
    std::vector<std::size_t> points;  // in the order given
  };
  glm::ivec3 cellOf(const glm::vec3& p) const { return glm::ivec3(glm::floor(p / cell_)); }
  static std::uint64_t key(const glm::ivec3& c) {
    return (std::uint64_t(std::uint32_t(c.x) & 0x1fffff) << 42) |
           (std::uint64_t(std::uint32_t(c.y) & 0x1fffff) << 21) |
           std::uint64_t(std::uint32_t(c.z) & 0x1fffff);
  }
  std::vector<glm::vec3> points_;
  float cell_;
  std::unordered_map<std::uint64_t, Cell> cells_;
  std::vector<glm::ivec3> occupied_;  // sorted by z, y, x
};

}  // namespace csm
