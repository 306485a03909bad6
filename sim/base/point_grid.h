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
      it->second.push_back(i);
    }
    std::sort(occupied_.begin(), occupied_.end(), [](const glm::ivec3& a, const glm::ivec3& b) {
      return std::make_tuple(a.z, a.y, a.x) < std::make_tuple(b.z, b.y, b.x);
    });
  }
  // f(j) for every point j within `radius` of p, in a fixed order: the cells by z, then y, then
  // x, each cell's points in the order given. A search wider than the grid has cells visits the
  // occupied ones, in the same order.
  template <class F>
  void within(const glm::vec3& p, float radius, F&& f) const {
    const int reach = int(std::ceil(radius / cell_));
    const glm::ivec3 c = cellOf(p);
    auto visit = [&](const std::vector<std::size_t>& list) {
      for (std::size_t j : list)
        if (glm::length(points_[j] - p) <= radius) f(j);
    };
    const std::size_t side = std::size_t(2 * reach + 1);
    if (side * side * side > occupied_.size()) {
      for (const glm::ivec3& o : occupied_)
        if (glm::all(glm::lessThanEqual(glm::abs(o - c), glm::ivec3(reach))))
          visit(cells_.at(key(o)));
      return;
    }
    for (int z = -reach; z <= reach; ++z)
      for (int y = -reach; y <= reach; ++y)
        for (int x = -reach; x <= reach; ++x) {
          const auto it = cells_.find(key(c + glm::ivec3(x, y, z)));
          if (it != cells_.end()) visit(it->second);
        }
  }

 private:
  glm::ivec3 cellOf(const glm::vec3& p) const { return glm::ivec3(glm::floor(p / cell_)); }
  static std::uint64_t key(const glm::ivec3& c) {
    return (std::uint64_t(std::uint32_t(c.x) & 0x1fffff) << 42) |
           (std::uint64_t(std::uint32_t(c.y) & 0x1fffff) << 21) |
           std::uint64_t(std::uint32_t(c.z) & 0x1fffff);
  }
  std::vector<glm::vec3> points_;
  float cell_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
  std::vector<glm::ivec3> occupied_;  // sorted by z, y, x
};

}  // namespace csm
