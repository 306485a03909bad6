#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include "sim/hairstyle.h"
#include "test_scenes.h"

using namespace csm;

TEST_CASE("a smaller strand count is a prefix of a larger one") {
  Config c = test::smallScene(300);
  c.hairstyle.curlRadius = 0.01f;
  const Groom big = test::growFor(c);
  c.hairstyle.strands = 120;
  const Groom small = test::growFor(c);
  REQUIRE(small.strandCount() == 120);
  REQUIRE(big.strandCount() == 300);
  for (size_t s = 0; s <= 120; ++s) CHECK(small.first[s] == big.first[s]);
  for (size_t i = 0; i < small.pointCount(); ++i) CHECK(small.points[i] == big.points[i]);
}

TEST_CASE("the generator is deterministic and the seed changes the hair") {
  Config c = test::smallScene(50);
  const Groom a = test::growFor(c), b = test::growFor(c);
  CHECK(a.points == b.points);
  c.hairstyle.seed = 2;
  const Groom d = test::growFor(c);
  CHECK(d.points != a.points);
}

TEST_CASE("particles per strand follow length and curl within the bounds") {
  Config c = test::smallScene(400);
  c.hairstyle.minParticles = 8;
  c.hairstyle.maxParticles = 25;
  c.hairstyle.segmentLength = 0.015f;
  c.hairstyle.lengthMin = 0.05f;
  c.hairstyle.lengthMax = 0.40f;
  const Groom straight = test::growFor(c);
  size_t fewest = 1000, most = 0;
  for (size_t s = 0; s < straight.strandCount(); ++s) {
    fewest = std::min<size_t>(fewest, straight.strandSize(s));
    most = std::max<size_t>(most, straight.strandSize(s));
  }
  CHECK(fewest == 8);
  CHECK(most == 25);
  CHECK(particlesForLength(c.hairstyle, 0.10) == 8);
  CHECK(particlesForLength(c.hairstyle, 0.15) == 11);
  c.hairstyle.curlRadius = 0.012f;
  c.hairstyle.curlStart = 0.3f;
  const Groom curly = test::growFor(c);
  CHECK(curly.pointCount() > straight.pointCount());  // curl adds arc length
  c.hairstyle.particlesPerStrand = 16;
  const Groom fixed = test::growFor(c);
  CHECK(fixed.pointCount() == 16 * fixed.strandCount());
}

TEST_CASE("roots sit on the scalp and the rest of the strand outside the head") {
  Config c = test::smallScene(500);
  c.hairstyle.curlRadius = 0.015f;
  const Groom g = test::growFor(c);
  const Sphere& scalp = c.head.spheres.front();
  for (size_t s = 0; s < g.strandCount(); ++s) {
    const uint32_t a = g.first[s];
    CHECK(std::abs(glm::length(g.points[a] - scalp.center) - scalp.radius) < 1e-5f);
    CHECK(g.points[a].y > scalp.center.y - scalp.radius * 0.35f);  // no hair on the chin
    for (uint32_t i = a + 1; i < g.first[s + 1]; ++i)
      for (const Sphere& sp : c.head.spheres)
        CHECK(glm::length(g.points[i] - sp.center) >= sp.radius + c.collision.radius);
  }
}
