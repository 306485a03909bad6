#include "sim/groom/resample.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "sim/base/parallel.h"

namespace csm::io {
namespace {

float pointSegmentDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * ab));
}

// Cumulative arc length at each point of the polyline.
std::vector<double> arcLengths(std::span<const glm::vec3> strand) {
  std::vector<double> s(strand.size(), 0.0);
  for (size_t i = 1; i < strand.size(); ++i) {
    s[i] = s[i - 1] + glm::length(glm::dvec3(strand[i]) - glm::dvec3(strand[i - 1]));
  }
  return s;
}

std::vector<glm::vec3> resampleAt(std::span<const glm::vec3> strand, const std::vector<double>& s,
                                  uint32_t count) {
  std::vector<glm::vec3> out(count);
  const double total = s.back();
  size_t seg = 0;
  for (uint32_t k = 0; k < count; ++k) {
    const double target = total * k / (count - 1);
    while (seg + 2 < strand.size() && s[seg + 1] < target) ++seg;
    const double len = s[seg + 1] - s[seg];
    const double t = len > 0.0 ? std::clamp((target - s[seg]) / len, 0.0, 1.0) : 0.0;
    out[k] = glm::vec3(glm::mix(glm::dvec3(strand[seg]), glm::dvec3(strand[seg + 1]), t));
  }
  // Root and tip exactly as in the file: the root is pinned to the scalp.
  out.front() = strand.front();
  out.back() = strand.back();
  return out;
}

// An upper bound of polylineDeviation() in O(n): original point i, at arc length s_i, is
// measured against the resampled segments around the one spanning s_i. A bound from above
// keeps the tolerance honest: the exact deviation is never larger.
// Stops early once the bound exceeds `limit`: a failed candidate's exact value is not needed.
float localDeviation(std::span<const glm::vec3> strand, const std::vector<double>& s,
                     const std::vector<glm::vec3>& resampled, float limit) {
  const size_t segments = resampled.size() - 1;
  const double step = s.back() / segments;
  float worst = 0.0f;
  for (size_t i = 0; i < strand.size(); ++i) {
    // Written so that a NaN (a strand of infinite length) gives segment 0, not a cast of NaN.
    const double at = s[i] / step;
    const auto j = at > 0.0 ? static_cast<size_t>(std::min<double>(at, segments - 1)) : size_t(0);
    float d = pointSegmentDistance(strand[i], resampled[j], resampled[j + 1]);
    if (j > 0) d = std::min(d, pointSegmentDistance(strand[i], resampled[j - 1], resampled[j]));
    if (j + 2 <= segments) {
      d = std::min(d, pointSegmentDistance(strand[i], resampled[j + 1], resampled[j + 2]));
    }
    worst = std::max(worst, d);
    if (worst > limit) break;
  }
  return worst;
}

}  // namespace

std::vector<glm::dvec3> resamplePolyline(std::span<const glm::dvec3> q, int n) {
  std::vector<double> s(q.size(), 0.0);
  for (size_t i = 1; i < q.size(); ++i) s[i] = s[i - 1] + glm::length(q[i] - q[i - 1]);
  std::vector<glm::dvec3> out(n);
  size_t j = 0;
  for (int i = 0; i < n; ++i) {
    const double target = s.back() * i / std::max(1, n - 1);
    while (j + 2 < q.size() && s[j + 1] < target) ++j;
    const double span = s[j + 1] - s[j];
    const double f = span > 0.0 ? std::clamp((target - s[j]) / span, 0.0, 1.0) : 0.0;
    out[i] = glm::mix(q[j], q[j + 1], f);
  }
  return out;
}

std::vector<glm::vec3> resampleStrand(std::span<const glm::vec3> strand, uint32_t count) {
  count = std::max<uint32_t>(count, 2);
  if (strand.empty()) return {};
  if (strand.size() == 1) return std::vector<glm::vec3>(count, strand.front());
  return resampleAt(strand, arcLengths(strand), count);
}

float polylineDeviation(std::span<const glm::vec3> original, std::span<const glm::vec3> resampled) {
  if (resampled.empty()) return 0.0f;
  float worst = 0.0f;
  for (const glm::vec3& p : original) {
    float d = glm::length(p - resampled.front());
    for (size_t k = 0; k + 1 < resampled.size(); ++k) {
      d = std::min(d, pointSegmentDistance(p, resampled[k], resampled[k + 1]));
    }
    worst = std::max(worst, d);
  }
  return worst;
}

ResampleStats resampleGroom(Groom& groom, const ResampleOptions& options) {
  const uint32_t minCount = std::max<uint32_t>(options.minParticles, 2);
  const uint32_t maxCount = std::max(options.maxParticles, minCount);
  ResampleStats stats;
  stats.pointsBefore = groom.pointCount();

  // Each strand on its own, in chunks of strands on the cores; the chunks' points and counts
  // joined in strand order, so the result does not depend on the cores.
  struct Chunk {
    std::vector<glm::vec3> points;
    std::vector<uint32_t> sizes;
    ResampleStats stats;
  };
  std::vector<Chunk> chunks(coreCount());
  parallelChunks(groom.strandCount(), 256, [&](size_t begin, size_t end, size_t c) {
    Chunk& out = chunks[c];
    for (size_t strandIndex = begin; strandIndex < end; ++strandIndex) {
      const std::span<const glm::vec3> strand(groom.points.data() + groom.first[strandIndex],
                                              groom.strandSize(strandIndex));
      const std::vector<double> s = arcLengths(strand);
      const bool inBounds = strand.size() >= minCount && strand.size() <= maxCount;
      if (inBounds || strand.size() < 2 || s.back() <= 0.0) {
        // Within bounds (its own points are exact), or nothing to resample along.
        out.points.insert(out.points.end(), strand.begin(), strand.end());
        out.sizes.push_back(uint32_t(strand.size()));
        ++out.stats.strandsKept;
        continue;
      }
      // Deviation is not monotonic in the count (a curl can alias with the spacing), so
      // walk up from the minimum rather than bisect.
      std::vector<glm::vec3> best;
      float bestDeviation = 0.0f;
      for (uint32_t count = minCount; count <= maxCount; ++count) {
        best = resampleAt(strand, s, count);
        const float limit =
            count < maxCount ? options.tolerance : std::numeric_limits<float>::infinity();
        bestDeviation = localDeviation(strand, s, best, limit);
        if (bestDeviation <= options.tolerance) break;
      }
      if (bestDeviation > options.tolerance) ++out.stats.strandsOverTolerance;
      out.stats.maxDeviation = std::max(out.stats.maxDeviation, bestDeviation);
      out.points.insert(out.points.end(), best.begin(), best.end());
      out.sizes.push_back(uint32_t(best.size()));
    }
  });
  std::vector<uint32_t> first{0};
  first.reserve(groom.first.size());
  std::vector<glm::vec3> points;
  size_t total = 0;
  for (const Chunk& c : chunks) total += c.points.size();
  points.reserve(total);
  for (const Chunk& c : chunks) {
    points.insert(points.end(), c.points.begin(), c.points.end());
    for (const uint32_t n : c.sizes) first.push_back(first.back() + n);
    stats.strandsKept += c.stats.strandsKept;
    stats.strandsOverTolerance += c.stats.strandsOverTolerance;
    stats.maxDeviation = std::max(stats.maxDeviation, c.stats.maxDeviation);
  }
  groom.first = std::move(first);
  groom.points = std::move(points);
  stats.pointsAfter = groom.pointCount();
  return stats;
}

}  // namespace csm::io
