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

// Found by fuzz_cyhair and fuzz_tressfx (tests/fuzz/regressions/): a groom file's points are
// finite, but the fit to the head could carry them past float's range (and on to NaN in the
// field's reads and the resampler's casts), or collapse a strand to a point.
TEST_CASE("a groom the fit carries out of float's range, or collapses, is refused") {
  Config c;
  c.hairstyle.strands = 10;
  // Roots 1e-37 apart: the automatic fit scales them up to the head (by ~1e36), and the tips,
  // 1000 units off, past float's largest value.
  Groom far;
  far.addStrand({{0, 0, 0}, {0, 1000, 0}, {0, 2000, 0}});
  far.addStrand({{1e-37f, 0, 0}, {1e-37f, 1000, 0}, {1e-37f, 2000, 0}});
  for (HeadShape shape : {HeadShape::Spheres, HeadShape::Sdf}) {
    c.collision.headShape = shape;
    Groom out;
    std::string error;
    CHECK_FALSE(fitFileGroom(c, far, "far.hair", out, &error));
    CHECK_THAT(error, Catch::Contains("far.hair: point 1 of strand 0 is not finite after fitting "
                                      "to the head"));
    CHECK_THAT(error, Catch::Contains("hairstyle.import_scale"));
  }
  // A given scale of 1e-30 takes a strand 1e-20 long below float's smallest value.
  Groom tiny;
  tiny.addStrand({{0, 0, 0}, {1e-20f, 0, 0}});
  c.collision.headShape = HeadShape::Spheres;
  c.hairstyle.importScale = 1e-30f;
  Groom out;
  std::string error;
  CHECK_FALSE(fitFileGroom(c, tiny, "tiny.hair", out, &error));
  CHECK_THAT(error, Catch::Contains("tiny.hair: strand 0 has zero length after fitting"));
  // And a sound groom still fits.
  c.hairstyle.importScale = 0.0f;
  Groom fine;
  fine.addStrand({{0, 10, 0}, {0, 5, 1}, {0, 0, 2}});
  fine.addStrand({{3, 9, 0}, {4, 5, 1}, {5, 0, 2}});
  CHECK(fitFileGroom(c, fine, "fine.hair", out, &error));
  CHECK(out.strandCount() == 2);
}
