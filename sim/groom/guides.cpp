#include "sim/groom/guides.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <queue>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "sim/base/parallel.h"
#include "sim/base/point_grid.h"

namespace csm {
namespace {

// What a strand is to the sampling: its root, and its shape as the way from the root to its
// middle and to its tip (by rest length), and its early direction (to a quarter of its length).
struct StrandShape {
  glm::vec3 root{0.0f}, middle{0.0f}, tip{0.0f}, early{0.0f};
  bool drawable = false;
};

// Shares of rest length from the root of every point of strand s, into `share`.
void restShares(const Groom& g, std::size_t s, std::vector<float>& share) {
  const std::uint32_t first = g.first[s], n = g.strandSize(s);
  double length = 0.0;
  std::vector<double> along(n, 0.0);
  for (std::uint32_t i = 1; i < n; ++i) {
    length += glm::length(glm::dvec3(g.points[first + i]) - glm::dvec3(g.points[first + i - 1]));
    along[i] = length;
  }
  for (std::uint32_t i = 0; i < n; ++i)
    share[first + i] =
        length > 0.0 ? float(along[i] / length) : float(i) / float(std::max(n, 2u) - 1);
  if (n > 0) share[first + n - 1] = n > 1 ? 1.0f : 0.0f;
}

glm::vec3 pointAtShare(const Groom& g, const std::vector<float>& share, std::size_t s, float u) {
  const std::uint32_t first = g.first[s], n = g.strandSize(s);
  for (std::uint32_t i = 1; i < n; ++i)
    if (share[first + i] >= u) {
      const float a = share[first + i - 1], b = share[first + i];
      const float t = b > a ? (u - a) / (b - a) : 0.0f;
      return g.points[first + i - 1] * (1.0f - t) + g.points[first + i] * t;
    }
  return g.points[first + n - 1];
}

// Every strand's shares, in chunks of strands on the cores.
void restSharesOf(const Groom& g, std::vector<float>& share) {
  parallelFor(g.strandCount(), 1024, [&](std::size_t begin, std::size_t end) {
    for (std::size_t s = begin; s < end; ++s) restShares(g, s, share);
  });
}

std::vector<StrandShape> shapesOf(const Groom& g, const std::vector<float>& share) {
  std::vector<StrandShape> out(g.strandCount());
  parallelFor(g.strandCount(), 1024, [&](std::size_t begin, std::size_t end) {
    for (std::size_t s = begin; s < end; ++s) {
      if (g.strandSize(s) < 2) continue;
      StrandShape& o = out[s];
      o.root = g.points[g.first[s]];
      o.middle = pointAtShare(g, share, s, 0.5f) - o.root;
      o.tip = g.points[g.first[s + 1] - 1] - o.root;
      const glm::vec3 e = pointAtShare(g, share, s, 0.25f) - o.root;
      o.early = glm::length(e) > 0.0f ? glm::normalize(e) : glm::vec3(0.0f, -1.0f, 0.0f);
      o.drawable = std::isfinite(glm::dot(o.root + o.middle + o.tip, glm::vec3(1.0f)));
    }
  });
  return out;
}

// The distance the sampling and the binding use: roots apart on the scalp, plus half the shapes
// apart. Never less than the roots' distance, which the grid below prunes by.
float strandDistance(const StrandShape& a, const StrandShape& b) {
  const glm::vec3 dm = a.middle - b.middle, dt = a.tip - b.tip;
  return glm::length(a.root - b.root) + 0.5f * std::sqrt(glm::dot(dm, dm) + glm::dot(dt, dt));
}

// The spacing of n roots spread over the box of `roots`' largest face.
float spacingOf(const std::vector<glm::vec3>& roots, std::size_t n) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& r : roots) lo = glm::min(lo, r), hi = glm::max(hi, r);
  const glm::vec3 e = glm::max(hi - lo, glm::vec3(1e-4f));
  const float area = std::max({e.x * e.y, e.y * e.z, e.z * e.x});
  return std::max(std::sqrt(area / float(std::max<std::size_t>(n, 1))), 1e-5f);
}

// The order of `points` along a Morton curve over their box (21 bits an axis): the index of the
// first, then the next; ties in the order given.
std::vector<std::uint32_t> curveOrder(const std::vector<glm::vec3>& points) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::vec3 scale = 2097151.0f / glm::max(hi - lo, glm::vec3(1e-30f));
  auto spread = [](std::uint64_t v) {  // 21 bits to every third of 63
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    return (v | v << 2) & 0x1249249249249249ULL;
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::uvec3 q(
        glm::clamp((points[i] - lo) * scale, glm::vec3(0.0f), glm::vec3(2097151.0f)));
    keyed[i] = {spread(q.x) | spread(q.y) << 1 | spread(q.z) << 2, std::uint32_t(i)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = keyed[i].second;
  return order;
}

}  // namespace

std::vector<std::uint32_t> chooseGuides(const Groom& groom, std::size_t count) {
  std::vector<float> share(groom.pointCount(), 0.0f);
  restSharesOf(groom, share);
  const std::vector<StrandShape> shapes = shapesOf(groom, share);
  std::vector<std::uint32_t> candidates;
  std::vector<glm::vec3> roots;
  for (std::size_t s = 0; s < shapes.size(); ++s)
    if (shapes[s].drawable) candidates.push_back(std::uint32_t(s)), roots.push_back(shapes[s].root);
  count = std::min(count, candidates.size());
  std::vector<std::uint32_t> chosen;
  if (count == 0) return chosen;
  // The strands in the order of their roots along a Morton curve, so that a grid cell's strands
  // lie close in memory whatever the cell's size (loading shapes scattered over a 100,000-strand
  // groom was half the sampling's time); `rank` keeps each one's place in the groom for ties.
  const std::vector<std::uint32_t> rank = curveOrder(roots);
  std::vector<std::uint32_t> local(rank.size());
  std::vector<StrandShape> shape(candidates.size());
  {
    std::vector<std::uint32_t> inGroom(candidates.size());
    for (std::size_t j = 0; j < rank.size(); ++j) {
      local[rank[j]] = std::uint32_t(j);
      inGroom[j] = candidates[rank[j]];
      shape[j] = shapes[inGroom[j]];
      roots[j] = shape[j].root;
    }
    candidates = std::move(inGroom);
  }
  // Farthest-point sampling: each strand's distance to the nearest guide; the largest found
  // through a heap of upper bounds (an entry holds the distance when it was pushed, never less
  // than now): a top that is no longer right goes back in with its distance now. Ties go to the
  // lower index. The first pick is the first drawable strand.
  std::vector<float> nearest(candidates.size(), INFINITY);
  using Entry = std::pair<float, std::int64_t>;  // distance, -index: the largest first
  std::priority_queue<Entry> heap;
  std::size_t pick = local[0];
  float reach = INFINITY;
  std::unique_ptr<PointGrid> grid;
  float cell = 0.0f;
  // Per grid cell, the largest distance to a guide among its strands (0 for guides): a cell
  // further from the new guide's root than that holds no strand the guide comes nearer to,
  // since a strand's distance is never less than its root's.
  std::vector<float> cellFarthest;
  while (chosen.size() < count) {
    chosen.push_back(candidates[pick]);
    nearest[pick] = 0.0f;
    const StrandShape g = shape[pick];
    auto lower = [&](std::size_t j) {
      nearest[j] = std::min(nearest[j], strandDistance(shape[j], g));
    };
    if (std::isinf(reach)) {
      for (std::size_t j = 0; j < candidates.size(); ++j) lower(j);
      std::vector<Entry> all;
      for (std::size_t j = 0; j < candidates.size(); ++j)
        all.push_back({nearest[j], -std::int64_t(rank[j])});
      heap = std::priority_queue<Entry>(std::less<Entry>(), std::move(all));
    } else {
      // Only strands whose roots lie within the largest distance left can come nearer to the
      // new guide. A grid of cells half that reach wide, made again as it halves: each query
      // looks at the 125 cells or so around the new guide, and skips those whose strands are
      // all nearer a guide than the cell is to the new one (half-reach cells skip more than
      // reach-wide ones: choosing 4,000 guides of 100,000 strands took 0.6-0.9 s against
      // 1.2-1.8, a quarter reach no less than half; 1.4 s before the skipping).
      if (!grid || reach < cell) {
        cell = std::max(0.5f * reach, 1e-6f);
        grid = std::make_unique<PointGrid>(roots, cell);
        cellFarthest.assign(grid->cells(), INFINITY);
      }
      grid->cellsNear(g.root, reach,
                      [&](std::size_t c, const std::vector<std::size_t>& in, float away) {
                        if (away > cellFarthest[c]) return;
                        float farthest = 0.0f;
                        for (std::size_t j : in) {
                          lower(j);
                          farthest = std::max(farthest, nearest[j]);
                        }
                        cellFarthest[c] = farthest;
                      });
    }
    bool found = false;
    while (!heap.empty()) {
      const auto [d, negIndex] = heap.top();
      const std::size_t j = local[std::size_t(-negIndex)];
      heap.pop();
      if (nearest[j] == 0.0f) continue;  // a guide
      if (d != nearest[j]) {
        heap.push({nearest[j], negIndex});
        continue;
      }
      heap.push({d, negIndex});
      pick = j;
      reach = d;
      found = true;
      break;
    }
    if (!found) break;
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

Groom FollowerBinding::guideGroom() const {
  Groom g;
  g.points.reserve(guideStrand.size() * 32);
  for (const std::uint32_t s : guideStrand) {
    g.points.insert(g.points.end(), drawn.points.begin() + drawn.first[s],
                    drawn.points.begin() + drawn.first[s + 1]);
    g.first.push_back(std::uint32_t(g.points.size()));
    g.addStrandData(drawn, s);
  }
  // What each guide stands for: its own strand (weight 1) and its share of every follower.
  std::vector<double> weight(guideStrand.size(), 0.0);
  for (std::size_t k = 0; k < guides.size() && k < weights.size(); ++k)
    for (int j = 0; j < kFollowerGuides; ++j)
      if (weights[k][j] > 0.0f) weight[guides[k][j]] += weights[k][j];
  g.weight.assign(weight.begin(), weight.end());
  return g;
}

FollowerBinding bindFollowers(Groom drawn, std::vector<std::uint32_t> guideStrand) {
  FollowerBinding b;
  b.drawn = std::move(drawn);
  b.guideStrand = std::move(guideStrand);
  const Groom& g = b.drawn;
  const std::size_t strands = g.strandCount();
  b.share.assign(g.pointCount(), 0.0f);
  restSharesOf(g, b.share);
  const std::vector<StrandShape> shapes = shapesOf(g, b.share);
  b.guides.assign(strands, glm::uvec4(0u));
  b.weights.assign(strands, glm::vec4(0.0f));
  if (b.guideStrand.empty()) return b;

  std::vector<glm::vec3> guideRoots;
  std::vector<std::int64_t> guideOf(strands, -1);
  for (std::size_t k = 0; k < b.guideStrand.size(); ++k) {
    guideRoots.push_back(shapes[b.guideStrand[k]].root);
    guideOf[b.guideStrand[k]] = std::int64_t(k);
  }
  const float spacing = spacingOf(guideRoots, guideRoots.size());
  const PointGrid grid(guideRoots, kBindRadius * spacing);
  struct Near {
    float d;
    std::uint32_t guide;
    bool operator<(const Near& o) const { return d != o.d ? d < o.d : guide < o.guide; }
  };
  // Each strand on its own: in chunks on the cores, the far ones counted per chunk.
  std::vector<std::size_t> far(coreCount(), 0);
  parallelChunks(strands, 256, [&](std::size_t begin, std::size_t end, std::size_t chunk) {
    std::vector<Near> near;
    for (std::size_t s = begin; s < end; ++s) {
      if (guideOf[s] >= 0) {
        b.guides[s].x = std::uint32_t(guideOf[s]);
        b.weights[s].x = 1.0f;
        continue;
      }
      const StrandShape& f = shapes[s];
      near.clear();
      // Guides near the root whose shape does not part from this strand's; further out while
      // there are none, and at last any guide (counted as far).
      const float closeBy = kBindRadius * spacing;
      float radius = closeBy;
      for (int round = 0; near.empty() && round < 24; ++round, radius *= 2.0f)
        grid.within(f.root, radius, [&](std::size_t k) {
          const StrandShape& gs = shapes[b.guideStrand[k]];
          if (glm::dot(gs.early, f.early) >= 0.5f)
            near.push_back({strandDistance(f, gs), std::uint32_t(k)});
        });
      if (near.empty())
        for (std::size_t k = 0; k < b.guideStrand.size(); ++k)
          near.push_back({strandDistance(f, shapes[b.guideStrand[k]]), std::uint32_t(k)});
      if (near.empty() || radius > 2.0f * closeBy) ++far[chunk];
      std::sort(near.begin(), near.end());
      const std::size_t used = std::min<std::size_t>(near.size(), kFollowerGuides);
      if (used == 0) continue;
      if (near[0].d <= 0.0f) {
        // The same strand as a guide: that guide alone, so it is followed to the float.
        b.guides[s].x = near[0].guide;
        b.weights[s].x = 1.0f;
        continue;
      }
      double sum = 0.0;
      glm::dvec4 w(0.0);
      for (std::size_t k = 0; k < used; ++k) {
        w[int(k)] = 1.0 / (double(near[k].d) * double(near[k].d));
        b.guides[s][int(k)] = near[k].guide;
        sum += w[int(k)];
      }
      w /= sum;
      b.weights[s] = glm::vec4(w);
      // Weights that sum to 1 in float: the largest takes what rounding left over.
      b.weights[s].x = 1.0f - (b.weights[s].y + b.weights[s].z + b.weights[s].w);
    }
  });
  for (const std::size_t n : far) b.farFollowers += n;
  return b;
}

}  // namespace csm
