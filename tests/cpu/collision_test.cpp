#include <catch2/catch.hpp>

#include <random>

#include <glm/geometric.hpp>

#include "sim/core/segment_pairs.h"

using namespace csm;

TEST_CASE("closest points of two segments", "[quick]") {
  double s, t;
  // Crossing at right angles, 0.1 apart.
  double d2 = closestSegmentPoints({-1, 0, 0}, {1, 0, 0}, {0, -1, 0.1}, {0, 1, 0.1}, s, t);
  CHECK(d2 == Approx(0.01));
  CHECK(s == Approx(0.5));
  CHECK(t == Approx(0.5));
  // Parallel, overlapping.
  d2 = closestSegmentPoints({0, 0, 0}, {1, 0, 0}, {0.5, 0.2, 0}, {1.5, 0.2, 0}, s, t);
  CHECK(d2 == Approx(0.04));
  // End to end.
  d2 = closestSegmentPoints({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, s, t);
  CHECK(d2 == Approx(1.0));
  CHECK(s == 1.0);
  CHECK(t == 0.0);
}

TEST_CASE("the grid finds exactly the pairs brute force finds", "[quick]") {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  std::vector<glm::dvec3> x;
  std::vector<uint32_t> strand;
  for (uint32_t s = 0; s < 150; ++s) {
    glm::dvec3 p(u(rng), u(rng), u(rng));
    const int n = 4 + int(s % 9);
    for (int i = 0; i < n; ++i) {
      x.push_back(p);
      strand.push_back(s);
      p += glm::dvec3(u(rng), u(rng), u(rng)) * 0.3;
    }
  }
  for (double r : {0.0005, 0.002, 0.01}) {
    const auto brute = findContactsBruteForce(x, strand, r);
    const auto grid = findContactsGrid(x, strand, r);
    INFO("distance " << r << ": brute force " << brute.size() << ", grid " << grid.size());
    CHECK(brute.size() > 0);
    CHECK(grid == brute);
  }
}

TEST_CASE("neighbouring segments of one strand are not contacts", "[quick]") {
  std::vector<glm::dvec3> x{{0, 0, 0}, {0.001, 0, 0}, {0.002, 0, 0}, {0.003, 0, 0}, {0.004, 0, 0}};
  std::vector<uint32_t> strand(5, 0);
  CHECK(findContactsBruteForce(x, strand, 0.01).size() == 1);  // only segments 0 and 3
  CHECK(findContactsGrid(x, strand, 0.01).size() == 1);
}
