// Fitting a file's groom onto the head: units, orientation, placement, root snapping.
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include <catch2/catch.hpp>

#include "sim/groom/fit.h"

using csm::Groom;
using csm::io::FitOptions;
using csm::io::Sphere;

namespace {

constexpr float kPi = 3.14159265358979f;

// A y-up groom in centimetres, as exported from a DCC tool: roots on a 9 cm scalp sphere
// centred at (3, 150, -2) covering polar angles 0..100 degrees, strands growing out along
// the normal then falling down.
Groom centimetreGroom() {
  const glm::vec3 centre(3, 150, -2);
  const float radius = 9.0f;
  Groom groom;
  for (int ring = 0; ring <= 5; ++ring) {
    const float theta = ring * 20.0f * kPi / 180.0f;
    const int around = ring == 0 ? 1 : 12;
    for (int k = 0; k < around; ++k) {
      const float phi = 2 * kPi * k / around + 0.1f * ring;
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                        std::sin(theta) * std::sin(phi));
      std::vector<glm::vec3> strand;
      glm::vec3 p = centre + radius * n;
      for (int i = 0; i < 30; ++i) {
        strand.push_back(p);
        p += 0.5f * glm::normalize(n + glm::vec3(0.05f, -0.2f * i, 0));
      }
      groom.addStrand(strand);
      groom.thickness.push_back(0.008f);  // 80 microns, in cm
    }
  }
  return groom;
}

glm::vec3 rootCentroid(const Groom& g) {
  glm::vec3 sum(0.0f);
  for (size_t s = 0; s < g.strandCount(); ++s) sum += g.points[g.first[s]];
  return sum / float(g.strandCount());
}

}  // namespace

TEST_CASE("boundingSphere is the smallest enclosing sphere", "[io][fit][quick]") {
  CHECK(csm::io::boundingSphere({}).radius == 0.0f);
  const Sphere two = csm::io::boundingSphere({{0, 0, 0}, {2, 0, 0}});
  CHECK(two.radius == Approx(1.0f));
  CHECK(glm::length(two.center - glm::vec3(1, 0, 0)) < 1e-6f);

  // Points on a sphere reaching past the equator: the sphere itself.
  std::vector<glm::vec3> cap;
  const Groom g = centimetreGroom();
  for (size_t s = 0; s < g.strandCount(); ++s) cap.push_back(g.points[g.first[s]]);
  const Sphere capSphere = csm::io::boundingSphere(cap);
  CHECK(capSphere.radius == Approx(9.0f).epsilon(1e-5));
  CHECK(glm::length(capSphere.center - glm::vec3(3, 150, -2)) < 1e-4f);

  // Random points: every one inside, radius within Jung's bounds (D/2 <= r <= D sqrt(3/8)).
  std::vector<glm::vec3> cloud;
  uint32_t state = 7;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / static_cast<float>(1u << 24);
  };
  for (int i = 0; i < 20000; ++i) cloud.push_back({next(), 3 * next(), next() * next()});
  const Sphere b = csm::io::boundingSphere(cloud);
  // far = max distance from one point, so far <= D <= 2 far.
  float far = 0, worst = 0;
  for (const glm::vec3& p : cloud) {
    worst = std::max(worst, glm::length(p - b.center) / b.radius);
    far = std::max(far, glm::length(p - cloud[0]));
  }
  CHECK(worst <= 1 + 1e-5f);
  CHECK(b.radius >= far / 2 * 0.9999f);
  CHECK(b.radius <= 2 * far * std::sqrt(3.0f / 8.0f) * 1.0001f);
  int onBoundary = 0;
  for (const glm::vec3& p : cloud) onBoundary += glm::length(p - b.center) > b.radius * 0.9999f;
  CHECK(onBoundary >= 2);
}

TEST_CASE("Auto fit scales and places a centimetre groom on the head", "[io][fit][quick]") {
  const Sphere head{{0.0f, 0.02f, 0.0f}, 0.095f};
  Groom groom = centimetreGroom();
  const Groom original = groom;
  FitOptions options;
  options.headSpheres = {{{0.0f, -0.1f, 0.0f}, 0.05f}, head};  // neck first: largest is used
  const auto report = csm::io::fitToHead(groom, options);

  CHECK(report.rootBoundingRadius == Approx(9.0f).epsilon(1e-5));
  CHECK(report.scale == Approx(0.095f / 9.0f).epsilon(1e-5));
  for (size_t s = 0; s < groom.strandCount(); ++s) {
    const glm::vec3 root = groom.points[groom.first[s]];
    CHECK(std::abs(glm::length(root - head.center) - head.radius) < 1e-5f);
    // Shape kept, scaled: the first segment has length 0.5 cm.
    CHECK(glm::length(groom.points[groom.first[s] + 1] - root) ==
          Approx(0.5f * report.scale).epsilon(1e-4));
  }
  CHECK(rootCentroid(groom).y > head.center.y + 0.3f * head.radius);
  CHECK(groom.thickness[0] == Approx(0.008f * report.scale));
  CHECK(groom.first == original.first);

  SECTION("a z-up groom comes right with rotationDeg") {
    Groom zUp = original;
    for (glm::vec3& p : zUp.points) p = {p.x, -p.z, p.y};  // Rx(+90): y-up -> z-up
    options.rotationDeg = {-90.0f, 0.0f, 0.0f};
    csm::io::fitToHead(zUp, options);
    for (size_t i = 0; i < zUp.points.size(); ++i) {
      CHECK(glm::length(zUp.points[i] - groom.points[i]) < 1e-5f);
    }
  }
  SECTION("offset is added after the automatic placement") {
    Groom moved = original;
    options.offset = {0.0f, 0.01f, 0.0f};
    csm::io::fitToHead(moved, options);
    CHECK(glm::length(moved.points[7] - groom.points[7] - options.offset) < 1e-6f);
  }
  SECTION("a given scale overrides the automatic one") {
    Groom scaled = original;
    options.scale = 0.01f;
    const auto r = csm::io::fitToHead(scaled, options);
    CHECK(r.scale == 0.01f);
    CHECK(glm::length(scaled.points[1] - scaled.points[0]) == Approx(0.005f).epsilon(1e-4));
  }
}

TEST_CASE("Rotation is Euler XYZ about the world axes, X first", "[io][fit][quick]") {
  Groom groom;
  groom.addStrand({{0, 1, 0}, {0, 2, 0}});
  FitOptions options;
  options.autoFit = false;
  options.rotationDeg = {90.0f, 90.0f, 0.0f};
  csm::io::fitToHead(groom, options);
  // Rx(90) takes +y to +z, then Ry(90) takes +z to +x.
  CHECK(glm::length(groom.points[0] - glm::vec3(1, 0, 0)) < 1e-6f);
}

TEST_CASE("Manual scale and offset without auto fit", "[io][fit][quick]") {
  Groom groom;
  groom.addStrand({{10, 20, 30}, {10, 25, 30}});
  FitOptions options;
  options.autoFit = false;
  options.scale = 0.01f;
  options.offset = {0, 1, 0};
  csm::io::fitToHead(groom, options);
  CHECK(glm::length(groom.points[0] - glm::vec3(0.1f, 1.2f, 0.3f)) < 1e-6f);
  CHECK(glm::length(groom.points[1] - glm::vec3(0.1f, 1.25f, 0.3f)) < 1e-6f);
}

TEST_CASE("Snapping puts every root on the nearest head sphere surface", "[io][fit][quick]") {
  const std::vector<Sphere> spheres = {{{0, 0, 0}, 0.1f}, {{0, -0.13f, 0.01f}, 0.05f}};
  Groom groom;
  uint32_t state = 3;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / static_cast<float>(1u << 24) * 2 - 1;
  };
  for (int s = 0; s < 500; ++s) {
    const glm::vec3 root(0.2f * next(), 0.25f * next() - 0.05f, 0.2f * next());
    groom.addStrand({root, root + glm::vec3(0, -0.01f, 0.002f), root + glm::vec3(0, -0.02f, 0)});
  }
  groom.addStrand({{0, 0, 0}, {0, -0.01f, 0}});  // a root at the centre: no normal
  const Groom before = groom;
  FitOptions options;
  options.autoFit = false;
  options.headSpheres = spheres;
  options.snapRoots = true;
  const auto report = csm::io::fitToHead(groom, options);
  CHECK(report.snappedStrands == groom.strandCount());

  for (size_t s = 0; s < groom.strandCount(); ++s) {
    const glm::vec3 root = groom.points[groom.first[s]];
    float gap = 1e9f;
    for (const Sphere& sphere : spheres) {
      gap = std::min(gap, std::abs(glm::length(root - sphere.center) - sphere.radius));
    }
    CHECK(gap < 1e-6f);
    // Not buried inside the other sphere, unless both radial projections of the original
    // root are (near the spheres' intersection circle).
    auto buried = [&](const glm::vec3& p) {
      for (const Sphere& sphere : spheres) {
        if (glm::length(p - sphere.center) < sphere.radius * (1 - 1e-3f)) return true;
      }
      return false;
    };
    bool avoidable = false;
    for (const Sphere& sphere : spheres) {
      const glm::vec3 d = before.points[before.first[s]] - sphere.center;
      const glm::vec3 n = glm::length(d) > 0 ? glm::normalize(d) : glm::vec3(0, 1, 0);
      avoidable |= !buried(sphere.center + sphere.radius * n);
    }
    if (avoidable) CHECK_FALSE(buried(root));
    // Rigid move: the strand keeps its shape.
    for (uint32_t i = groom.first[s] + 1; i < groom.first[s + 1]; ++i) {
      const glm::vec3 was = before.points[i] - before.points[before.first[s]];
      CHECK(glm::length((groom.points[i] - root) - was) < 1e-6f);
    }
  }
  // The centre root went straight up.
  CHECK(glm::length(groom.points[groom.first.back() - 2] - glm::vec3(0, 0.1f, 0)) < 1e-6f);
}

TEST_CASE("Auto fit of a single strand stays finite", "[io][fit][quick]") {
  Groom groom;
  groom.addStrand({{5, 5, 5}, {5, 4, 5}});
  FitOptions options;
  const auto report = csm::io::fitToHead(groom, options);
  CHECK(report.scale == 1.0f);
  for (const glm::vec3& p : groom.points) CHECK(std::isfinite(p.x + p.y + p.z));
}
