#include "sim/core/segment_pairs.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <glm/geometric.hpp>

#include "sim/base/parallel.h"

namespace csm {
namespace {

bool segmentExists(std::span<const uint32_t> strand, uint32_t i) {
  return i + 1 < strand.size() && strand[i] == strand[i + 1];
}

bool mayTouch(std::span<const uint32_t> strand, uint32_t a, uint32_t b) {
  if (strand[a] != strand[b]) return true;
  return (a > b ? a - b : b - a) > kStrandGap;
}

void testPair(std::span<const glm::dvec3> x, uint32_t a, uint32_t b, double maxDistance,
              std::vector<SegmentPair>& out) {
  double s, t;
  double d2 = closestSegmentPoints(x[a], x[a + 1], x[b], x[b + 1], s, t);
  if (d2 < maxDistance * maxDistance) out.push_back({a, b, s, t, std::sqrt(d2)});
}

}  // namespace

double closestSegmentPoints(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& q0,
                            const glm::dvec3& q1, double& s, double& t) {
  const glm::dvec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  const double eps = 1e-20;
  if (a <= eps && e <= eps) {
    s = t = 0.0;
  } else if (a <= eps) {
    s = 0.0;
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = glm::dot(d1, r);
    if (e <= eps) {
      t = 0.0;
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = glm::dot(d1, d2);
      const double denom = a * e - b * b;
      s = denom > eps * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  const glm::dvec3 diff = (p0 + d1 * s) - (q0 + d2 * t);
  return glm::dot(diff, diff);
}

std::vector<SegmentPair> findContactsBruteForce(std::span<const glm::dvec3> x,
                                                std::span<const uint32_t> strand,
                                                double maxDistance) {
  std::vector<SegmentPair> out;
  const uint32_t n = uint32_t(x.size());
  for (uint32_t a = 0; a < n; ++a) {
    if (!segmentExists(strand, a)) continue;
    for (uint32_t b = a + 1; b < n; ++b)
      if (segmentExists(strand, b) && mayTouch(strand, a, b)) testPair(x, a, b, maxDistance, out);
  }
  return out;
}

std::vector<SegmentPair> findContactsGrid(std::span<const glm::dvec3> x,
                                          std::span<const uint32_t> strand, double maxDistance,
                                          uint64_t* oversize) {
  std::vector<SegmentPair> out;
  if (oversize) *oversize = 0;
  const uint32_t n = uint32_t(x.size());
  std::vector<uint32_t> segments;
  std::vector<double> lengths;
  for (uint32_t i = 0; i < n; ++i)
    if (segmentExists(strand, i)) {
      const double length = glm::length(x[i + 1] - x[i]);
      // A segment with a non-finite end (a simulation that blew up) is in no cell: its
      // cell index would be undefined.
      if (!std::isfinite(length)) {
        if (oversize) ++*oversize;
        continue;
      }
      segments.push_back(i);
      lengths.push_back(length);
    }
  if (segments.empty()) return out;
  // Each segment goes into every cell its box (inflated by half the contact distance) touches,
  // so cells can be much smaller than a segment: in dense hair a cell as long as a segment
  // holds hundreds of them, and the 27-cell search around a midpoint tests thousands of pairs
  // per segment. A pair is tested only in the cell holding the lowest corner of the overlap of
  // the two boxes, so it is found exactly once. The median length sets the cell, so that a few
  // segments stretched far (an exploding simulation) do not put all the hair in one cell.
  std::vector<double> sorted = lengths;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double cell = std::max(2.0 * maxDistance, 0.5 * sorted[sorted.size() / 2]);
  // Each segment's box padded by half the contact distance, once: a pair whose boxes do not
  // overlap is farther apart than maxDistance along some axis, so its closest points are never
  // computed (in dense hair most pairs of a cell).
  const double pad = 0.5 * maxDistance;
  std::vector<glm::dvec3> low(n), high(n);
  for (uint32_t i : segments) {
    low[i] = glm::min(x[i], x[i + 1]) - pad;
    high[i] = glm::max(x[i], x[i + 1]) + pad;
  }
  auto cellOf = [&](const glm::dvec3& p) {
    return glm::i64vec3(std::floor(p.x / cell), std::floor(p.y / cell), std::floor(p.z / cell));
  };
  // A segment whose box spans more cells than this along an axis (16 median segments: no hair
  // the strain limit holds) is left out and counted, so the search stays bounded in time and
  // memory whatever the positions; the cell indices of the rest stay far inside int64.
  constexpr double kMaxCellsPerAxis = 32.0;
  {
    size_t kept = 0;
    for (uint32_t i : segments) {
      const glm::dvec3 span = (high[i] - low[i]) / cell;
      const glm::dvec3 at = glm::abs(low[i]) / cell;
      if (std::max({span.x, span.y, span.z}) > kMaxCellsPerAxis ||
          std::max({at.x, at.y, at.z}) > 1e15) {
        if (oversize) ++*oversize;
        continue;
      }
      segments[kept++] = i;
    }
    segments.resize(kept);
  }
  struct Entry {
    glm::i64vec3 c;
    uint32_t seg;
  };
  std::vector<Entry> entries;
  entries.reserve(segments.size() * 4);
  for (uint32_t i : segments) {
    const glm::i64vec3 lo = cellOf(low[i]), hi = cellOf(high[i]);
    for (int64_t cx = lo.x; cx <= hi.x; ++cx)
      for (int64_t cy = lo.y; cy <= hi.y; ++cy)
        for (int64_t cz = lo.z; cz <= hi.z; ++cz) entries.push_back({{cx, cy, cz}, i});
  }
  auto less = [](const Entry& l, const Entry& r) {
    if (l.c.x != r.c.x) return l.c.x < r.c.x;
    if (l.c.y != r.c.y) return l.c.y < r.c.y;
    if (l.c.z != r.c.z) return l.c.z < r.c.z;
    return l.seg < r.seg;
  };
  std::sort(entries.begin(), entries.end(), less);
  std::vector<size_t> runs;  // where each cell's entries begin
  for (size_t i = 0; i < entries.size(); ++i)
    if (i == 0 || entries[i].c != entries[i - 1].c) runs.push_back(i);
  runs.push_back(entries.size());
  std::vector<std::vector<SegmentPair>> found(coreCount());
  parallelChunks(runs.size() - 1, 256, [&](size_t first, size_t last, size_t chunk) {
    std::vector<SegmentPair>& mine = found[chunk];
    for (size_t r = first; r < last; ++r) {
      const size_t begin = runs[r], end = runs[r + 1];
      // The cell's entries by their boxes' lowest x (then index: a fixed order), so each one
      // meets only those that start before its box ends along x (sort and sweep).
      std::sort(entries.begin() + ptrdiff_t(begin), entries.begin() + ptrdiff_t(end),
                [&](const Entry& l, const Entry& r) {
                  return low[l.seg].x != low[r.seg].x ? low[l.seg].x < low[r.seg].x : l.seg < r.seg;
                });
      for (size_t i = begin; i < end; ++i) {
        const uint32_t a = entries[i].seg;
        const glm::dvec3 la = low[a], ha = high[a];
        for (size_t j = i + 1; j < end && low[entries[j].seg].x <= ha.x; ++j) {
          const uint32_t b = entries[j].seg;
          const glm::dvec3& lb = low[b];
          const glm::dvec3& hb = high[b];
          if (ha.y < lb.y || hb.y < la.y || ha.z < lb.z || hb.z < la.z) continue;
          if (!mayTouch(strand, a, b)) continue;
          if (cellOf(glm::max(la, lb)) != entries[begin].c) continue;
          // Lower index first, as the pairs are listed and every solver evaluates them.
          testPair(x, std::min(a, b), std::max(a, b), maxDistance, mine);
        }
      }
    }
  });
  for (const auto& part : found) out.insert(out.end(), part.begin(), part.end());
  std::sort(out.begin(), out.end(), [](const SegmentPair& l, const SegmentPair& r) {
    return l.a != r.a ? l.a < r.a : l.b < r.b;
  });
  return out;
}

glm::dvec3 separationDirection(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& q0,
                               const glm::dvec3& q1, double s, double t, double d) {
  const glm::dvec3 between = glm::mix(p0, p1, s) - glm::mix(q0, q1, t);
  if (d > 1e-12) return between / d;
  const glm::dvec3 n = glm::cross(p1 - p0, q1 - q0);
  const double len = glm::length(n);
  return len > 1e-15 ? n / len : glm::dvec3(0.0, 1.0, 0.0);
}

}  // namespace csm
