// Guides and followers (sim/groom/guides.h, sim/groom/followers.h): which strands are simulated,
// how the others are bound to them, and how they follow.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "sim/groom/followers.h"
#include "sim/groom/guides.h"
#include "sim/solver/cpu_solver.h"
#include "sim/run/simulation.h"
#include "test_scenes.h"

using namespace csm;

namespace {

// The largest distance from a root to the nearest guide's root.
float coverage(const Groom& g, const std::vector<uint32_t>& guides) {
  float worst = 0.0f;
  for (size_t s = 0; s < g.strandCount(); ++s) {
    float best = std::numeric_limits<float>::infinity();
    for (uint32_t k : guides)
      best = std::min(best, glm::length(g.points[g.first[s]] - g.points[g.first[k]]));
    worst = std::max(worst, best);
  }
  return worst;
}

// World positions of the guides at rest with the head at `pose`.
std::vector<glm::vec3> posedGuides(const FollowerBinding& b, const Pose& pose) {
  std::vector<glm::vec3> out;
  const Groom guides = b.guideGroom();
  for (const glm::vec3& p : guides.points) out.push_back(glm::vec3(pose.apply(glm::dvec3(p))));
  return out;
}

// Strands along a line of roots at x in [-0.05, 0.05], parted at x = 0: the left ones run out
// to -x, the right ones to +x, each 10 points.
Groom partedGroom(int perSide) {
  Groom g;
  for (int side = -1; side <= 1; side += 2)
    for (int i = 0; i < perSide; ++i) {
      const float x = float(side) * (0.0005f + 0.05f * float(i) / float(perSide));
      for (int row = 0; row < 2; ++row) {
        std::vector<glm::vec3> pts;
        const glm::vec3 root(x, 0.1f, 0.004f * float(row));
        for (int k = 0; k < 10; ++k)
          pts.push_back(root + float(k) / 9.0f * glm::vec3(0.1f * float(side), -0.05f, 0.0f));
        g.addStrand(pts);
      }
    }
  return g;
}

// Whether point i is a strand's root (where the groom put it: on the scalp, not moved).
bool isRoot(const Groom& g, size_t i) {
  return std::binary_search(g.first.begin(), g.first.end(), uint32_t(i));
}

}  // namespace

TEST_CASE("hairstyle.guides: every strand, a count, or auto", "[guides][quick]") {
  CHECK(guideCount(0, 1234) == 1234);
  CHECK(guideCount(100, 1234) == 100);
  CHECK(guideCount(5000, 1234) == 1234);
  CHECK(guideCount(-1, kAutoGuideThreshold) == kAutoGuideThreshold);
  CHECK(guideCount(-1, kAutoGuideThreshold + 1) == kAutoGuides);
}

TEST_CASE("the guides are chosen deterministically and spread over the scalp", "[guides][quick]") {
  const Groom g = test::growFor(test::smallScene(1200));
  const std::vector<uint32_t> a = chooseGuides(g, 100), b = chooseGuides(g, 100);
  REQUIRE(a.size() == 100);
  CHECK(a == b);
  CHECK(std::is_sorted(a.begin(), a.end()));
  CHECK(std::adjacent_find(a.begin(), a.end()) == a.end());
  // Farther-point sampling covers the scalp better than every twelfth strand does.
  std::vector<uint32_t> stride;
  for (uint32_t s = 0; s < 1200; s += 12) stride.push_back(s);
  CHECK(coverage(g, a) < 0.8f * coverage(g, stride));
  // Asking for every strand gives every strand.
  CHECK(chooseGuides(g, 5000).size() == g.strandCount());
}

TEST_CASE("a follower's weights sum to 1, and a guide follows itself alone", "[guides][quick]") {
  const Groom g = test::growFor(test::smallScene(800));
  const std::vector<uint32_t> guides = chooseGuides(g, 60);
  const FollowerBinding b = bindFollowers(g, guides);
  const FollowerBinding again = bindFollowers(g, guides);
  REQUIRE(b.guides.size() == g.strandCount());
  CHECK(std::memcmp(b.guides.data(), again.guides.data(), b.guides.size() * 16) == 0);
  CHECK(std::memcmp(b.weights.data(), again.weights.data(), b.weights.size() * 16) == 0);
  int multi = 0;
  for (size_t s = 0; s < g.strandCount(); ++s) {
    const glm::vec4 w = b.weights[s];
    CHECK(std::abs(w.x + w.y + w.z + w.w - 1.0f) < 1e-6f);
    for (int k = 0; k < 4; ++k) {
      CHECK(w[k] >= 0.0f);
      if (w[k] > 0.0f) CHECK(b.guides[s][k] < guides.size());
    }
    multi += w.y > 0.0f;
  }
  for (size_t k = 0; k < guides.size(); ++k) {
    CHECK(b.guides[guides[k]].x == k);
    CHECK(b.weights[guides[k]] == glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
  }
  CHECK(multi > int(g.strandCount()) / 2);  // most followers blend several guides
  CHECK(b.guideGroom().strandCount() == guides.size());
}

TEST_CASE("each guide weighs its own strand and its followers' shares of it", "[guides][quick]") {
  const Groom g = test::growFor(test::smallScene(800));
  const std::vector<uint32_t> guides = chooseGuides(g, 60);
  const FollowerBinding b = bindFollowers(g, guides);
  const Groom simulated = b.guideGroom();
  REQUIRE(simulated.weight.size() == guides.size());
  // Together the guides stand for the whole groom; each for at least itself.
  double total = 0.0;
  for (float w : simulated.weight) {
    CHECK(w >= 1.0f);
    total += w;
  }
  CHECK(total == Approx(double(g.strandCount())).epsilon(1e-5));
  // And one guide's weight is its followers' shares of it, summed, with its own 1.
  const size_t k = guides.size() / 2;
  double expected = 0.0;
  for (size_t s = 0; s < g.strandCount(); ++s)
    for (int j = 0; j < kFollowerGuides; ++j)
      if (b.weights[s][j] > 0.0f && b.guides[s][j] == k) expected += b.weights[s][j];
  CHECK(simulated.weight[k] == Approx(expected).epsilon(1e-6));
  CHECK(simulated.weight[k] > 2.0f);  // 800 strands through 60 guides: about 13 each
  // A groom whose every strand is simulated carries no weights: each stands for itself.
  CHECK(g.weight.empty());
  CHECK(g.weightOf(0) == 1.0f);
}

TEST_CASE("followers keep the groom's rest shape when the guides are at rest", "[guides][quick]") {
  const Config c = test::smallScene(600);
  const Groom g = test::growFor(c);
  const FollowerBinding b = bindFollowers(g, chooseGuides(g, 40));
  const Pose pose = rotationAbout(glm::dvec3(0.0, 0.0, 0.0), glm::dvec3(1.0, 0.0, 0.0), 20.0);
  std::vector<glm::vec3> drawn;
  makeFollowers(b, posedGuides(b, pose), pose, SceneHead{}, drawn);
  REQUIRE(drawn.size() == g.pointCount());
  float worst = 0.0f;
  for (size_t i = 0; i < drawn.size(); ++i)
    worst = std::max(worst, glm::length(drawn[i] - glm::vec3(pose.apply(glm::dvec3(g.points[i])))));
  CHECK(worst < 2e-6f);
}

TEST_CASE("a follower equal to its guide follows it to the float", "[guides][quick]") {
  Groom g = test::growFor(test::smallScene(200));
  // Strand 0 again, as the last strand: the same points, not a guide.
  g.addStrand(std::vector<glm::vec3>(g.points.begin() + g.first[0], g.points.begin() + g.first[1]));
  const size_t copy = g.strandCount() - 1;
  std::vector<uint32_t> guides = chooseGuides(g, 30);
  guides.erase(std::remove(guides.begin(), guides.end(), uint32_t(copy)), guides.end());
  if (std::find(guides.begin(), guides.end(), 0u) == guides.end())
    guides.insert(guides.begin(), 0u);
  const FollowerBinding b = bindFollowers(g, guides);
  CHECK(b.weights[copy] == glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
  // The guides swung and bent: every point moved and turned.
  std::vector<glm::vec3> x = posedGuides(b, Pose{});
  for (size_t i = 0; i < x.size(); ++i)
    x[i] += glm::vec3(0.01f * std::sin(float(i)), 0.02f * std::cos(0.3f * float(i)), 0.005f);
  const Pose pose = rotationAbout(glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0), 10.0);
  std::vector<glm::vec3> drawn;
  makeFollowers(b, x, pose, SceneHead{}, drawn);
  const uint32_t n = g.strandSize(0);
  for (uint32_t i = 0; i < n; ++i) {
    INFO("point " << i);
    CHECK(drawn[g.first[copy] + i] == x[i]);  // guide 0 is strand 0: its particles come first
    CHECK(drawn[g.first[0] + i] == x[i]);
  }
}

TEST_CASE("followers stay on their side of a parting when its guides are pulled apart",
          "[guides][quick]") {
  const Groom g = partedGroom(40);
  const FollowerBinding b = bindFollowers(g, chooseGuides(g, 16));
  // Both sides have guides.
  int left = 0, right = 0;
  for (uint32_t s : b.guideStrand) (g.points[g.first[s]].x < 0.0f ? left : right)++;
  REQUIRE(left > 2);
  REQUIRE(right > 2);
  // Each side's guides pulled 3 cm further out to its side, roots where they are.
  std::vector<glm::vec3> x = posedGuides(b, Pose{});
  const Groom guides = b.guideGroom();
  for (size_t k = 0; k < guides.strandCount(); ++k) {
    const float side = guides.points[guides.first[k]].x < 0.0f ? -1.0f : 1.0f;
    for (uint32_t i = guides.first[k] + 1; i < guides.first[k + 1]; ++i)
      x[i].x += side * 0.03f * float(i - guides.first[k]) / 9.0f;
  }
  std::vector<glm::vec3> drawn;
  makeFollowers(b, x, Pose{}, SceneHead{}, drawn);
  for (size_t s = 0; s < g.strandCount(); ++s) {
    const float side = g.points[g.first[s]].x < 0.0f ? -1.0f : 1.0f;
    const uint32_t tip = g.first[s + 1] - 1;
    INFO("strand " << s << " root x " << g.points[g.first[s]].x);
    CHECK(side * (drawn[tip].x - g.points[tip].x) > 0.025f);
  }
  CHECK(b.farFollowers == 0);
}

TEST_CASE("no follower point is left inside the head", "[guides][quick]") {
  const Config c = test::smallScene(600);
  const std::shared_ptr<const HeadModel> head = HeadModel::require(c);
  const Groom g = growHairstyle(c, *head);
  const FollowerBinding b = bindFollowers(g, chooseGuides(g, 30));
  // The guides sunk into the head: every point but the root pulled a third of the way to the
  // head's centre. (Roots stay where the groom put them.)
  std::vector<glm::vec3> x = posedGuides(b, Pose{});
  const Groom guides = b.guideGroom();
  for (size_t k = 0; k < guides.strandCount(); ++k)
    for (uint32_t i = guides.first[k] + 1; i < guides.first[k + 1]; ++i) x[i] *= 0.67f;
  std::vector<glm::vec3> drawn;
  SECTION("the head's field") {
    const SceneHead collider{&head->shapeField(), {}, nullptr, {}};
    const FollowerStats stats = makeFollowers(b, x, Pose{}, collider, drawn);
    CHECK(stats.pushed > g.strandCount());
    CHECK(stats.deepest < 1e-4);
    double deepest = 0.0;
    for (size_t i = 0; i < drawn.size(); ++i)
      if (!isRoot(g, i)) deepest = std::min(deepest, collider.field->sample(drawn[i]));
    CHECK(deepest > -1e-4);
  }
  SECTION("the head's spheres") {
    const SceneHead collider{nullptr, head->spheres(), nullptr, {}};
    REQUIRE(!collider.spheres.empty());
    const FollowerStats stats = makeFollowers(b, x, Pose{}, collider, drawn);
    CHECK(stats.pushed > g.strandCount());
    CHECK(stats.deepest < 1e-5);
    double deepest = 0.0;
    for (size_t i = 0; i < drawn.size(); ++i)
      for (const Sphere& sp : collider.spheres)
        if (!isRoot(g, i))
          deepest = std::min(deepest, double(glm::length(drawn[i] - sp.center) - sp.radius));
    CHECK(deepest > -1e-5);
  }
}

TEST_CASE("a scene simulated through guides draws every strand", "[guides][quick]") {
  Config c = test::smallScene(400);
  c.hairstyle.guides = 40;
  std::string error;
  Simulation sim(std::make_unique<CpuSolver>());
  REQUIRE(sim.load(c, "", &error));
  CHECK(sim.counts().strands == 40);
  CHECK(sim.groom().strandCount() == 40);
  REQUIRE(sim.followers());
  CHECK(sim.drawnStrands() == 400);
  for (int f = 0; f < 5; ++f) sim.stepFrame();
  std::vector<glm::vec4> x, drawn;
  sim.readPositions(x);
  sim.drawnPositions(x, drawn);
  REQUIRE(drawn.size() == sim.followers()->drawn.pointCount());
  for (const glm::vec4& p : drawn) REQUIRE(std::isfinite(p.x + p.y + p.z));
  // The roots go with the head.
  const Groom& all = sim.followers()->drawn;
  for (size_t s = 0; s < all.strandCount(); ++s) {
    const glm::vec3 root(sim.headPose().apply(glm::dvec3(all.points[all.first[s]])));
    CHECK(glm::length(glm::vec3(drawn[all.first[s]]) - root) < 1e-5f);
  }
  // 0: every strand simulated, as before guides existed.
  c.hairstyle.guides = 0;
  REQUIRE(sim.setConfig(c, &error));
  CHECK(sim.counts().strands == 400);
  CHECK(!sim.followers());
}
