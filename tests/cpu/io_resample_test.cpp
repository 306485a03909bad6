// Resampling strands to the solver's particle counts: bounds, tolerance, root and tip kept.
#include <cmath>
#include <cstring>
#include <span>
#include <vector>

#include <glm/geometric.hpp>

#include <catch2/catch.hpp>

#include "sim/groom/resample.h"

using csm::Groom;
using csm::io::ResampleOptions;

namespace {

constexpr float kPi = 3.14159265358979f;

std::vector<glm::vec3> straightStrand(int n, float length) {
  std::vector<glm::vec3> s;
  for (int i = 0; i < n; ++i) s.push_back({0.01f, 0.1f - length * i / (n - 1), 0.02f});
  return s;
}

// Straight near the root, then a helix of the given radius: the paper's Fig. 3 hair.
std::vector<glm::vec3> curlyStrand(int n, float curlRadius, float turns) {
  std::vector<glm::vec3> s;
  for (int i = 0; i < n; ++i) {
    const float t = float(i) / (n - 1);
    if (t < 0.3f) {
      s.push_back({0, -0.1f * t, 0});
    } else {
      const float u = (t - 0.3f) / 0.7f;
      const float a = 2 * kPi * turns * u;
      s.push_back({curlRadius * (1 - std::cos(a)), -0.03f - 0.2f * u, curlRadius * std::sin(a)});
    }
  }
  return s;
}

std::span<const glm::vec3> strandOf(const Groom& g, size_t s) {
  return {g.points.data() + g.first[s], g.strandSize(s)};
}

}  // namespace

TEST_CASE("A 200-point straight strand shrinks to the minimum", "[io][resample][quick]") {
  Groom groom;
  const auto original = straightStrand(200, 0.3f);
  groom.addStrand(original);
  groom.color.push_back({0.2f, 0.1f, 0.05f});
  groom.thickness.push_back(7e-5f);
  const auto stats = csm::io::resampleGroom(groom, ResampleOptions{8, 25, 1e-4f});
  CHECK(stats.pointsBefore == 200);
  CHECK(stats.pointsAfter == 8);
  CHECK(stats.pointsSaved() == 192);
  CHECK(stats.strandsOverTolerance == 0);
  REQUIRE(groom.first == std::vector<uint32_t>{0, 8});
  CHECK(groom.points.front() == original.front());
  CHECK(groom.points.back() == original.back());
  for (size_t i = 1; i < 8; ++i) {
    CHECK(glm::length(groom.points[i] - groom.points[i - 1]) == Approx(0.3f / 7).epsilon(1e-4));
  }
  CHECK(groom.color.size() == 1);
  CHECK(groom.thickness == std::vector<float>{7e-5f});
}

TEST_CASE("Curly strands meet the tolerance with the fewest particles", "[io][resample][quick]") {
  const auto original = curlyStrand(200, 0.006f, 2.5f);
  uint32_t previousCount = 0;
  for (const float tolerance : {5e-3f, 2e-3f, 1e-3f}) {
    CAPTURE(tolerance);
    Groom groom;
    groom.addStrand(original);
    const auto stats = csm::io::resampleGroom(groom, ResampleOptions{8, 25, tolerance});
    REQUIRE(stats.strandsOverTolerance == 0);
    const uint32_t count = groom.strandSize(0);
    CHECK(count >= 8);
    CHECK(count <= 25);
    // The exact deviation (distance of every original point to the new polyline).
    const float deviation = csm::io::polylineDeviation(original, strandOf(groom, 0));
    CHECK(deviation <= tolerance);
    CHECK(stats.maxDeviation >= deviation * 0.999f);  // the library's bound is conservative
    // One particle fewer would not do (unless already at the minimum).
    if (count > 8) {
      const auto fewer = csm::io::resampleStrand(original, count - 1);
      CHECK(csm::io::polylineDeviation(original, fewer) > tolerance * 0.5f);
    }
    CHECK(count >= previousCount);
    previousCount = count;
    CHECK(groom.points.front() == original.front());
    CHECK(groom.points.back() == original.back());
  }
}

TEST_CASE("Strands that cannot meet the tolerance get the maximum", "[io][resample][quick]") {
  Groom groom;
  groom.addStrand(curlyStrand(200, 0.004f, 12.0f));
  const auto stats = csm::io::resampleGroom(groom, ResampleOptions{8, 25, 1e-4f});
  CHECK(groom.strandSize(0) == 25);
  CHECK(stats.strandsOverTolerance == 1);
  CHECK(stats.maxDeviation > 1e-4f);
}

TEST_CASE("Strands within the bounds keep their points, short ones grow", "[io][resample]") {
  Groom groom;
  const auto inBounds = curlyStrand(12, 0.01f, 1.0f);
  groom.addStrand(inBounds);
  groom.addStrand(straightStrand(3, 0.1f));
  groom.addStrand(straightStrand(150, 0.2f));
  const auto stats = csm::io::resampleGroom(groom, ResampleOptions{8, 25, 1e-3f});
  REQUIRE(groom.strandCount() == 3);
  CHECK(stats.strandsKept == 1);
  REQUIRE(groom.strandSize(0) == 12);
  CHECK(std::memcmp(&groom.points[0], inBounds.data(), 12 * sizeof(glm::vec3)) == 0);
  CHECK(groom.strandSize(1) == 8);  // upsampled to the minimum along the same line
  CHECK(groom.strandSize(2) == 8);
  CHECK(stats.pointsBefore == 165);
  CHECK(stats.pointsAfter == 28);
  CHECK(groom.first.back() == groom.points.size());
}

TEST_CASE("Resample options are clamped to sane bounds", "[io][resample][quick]") {
  Groom groom;
  groom.addStrand(straightStrand(40, 0.1f));
  csm::io::resampleGroom(groom, ResampleOptions{0, 1, 1e-3f});
  CHECK(groom.strandSize(0) == 2);
}
