// Scenes of the strand-contact tests, shared by the CPU and GPU suites.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "sim/core/segment_pairs.h"
#include "sim/core/config.h"
#include "sim/core/groom.h"

namespace csm::test {

// A short bar, held whole by its root (every particle within the root length), and a soft
// strand 3 mm above it, held for its first 5-6 cm, that crosses over the bar's middle 2-3 cm
// past the held piece: gravity lays the free part over the bar. The bar is strand 0 (particles
// 0-2), the strand strand 1. `offset` moves the strand along the bar and its particles along
// itself (0: the two cross where a particle of each lies).
inline Groom drapeGroom(float offset = 0.0f) {
  Groom g;
  g.addStrand({glm::vec3(-0.025f, 0.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.025f, 0.0f, 0.0f)});
  std::vector<glm::vec3> p;
  for (int i = 0; i <= 20; ++i) p.emplace_back(offset, 0.003f, -0.08f + offset + 0.01f * float(i));
  g.addStrand(p);
  return g;
}

inline Config drapeConfig() {
  Config c;
  c.head.spheres.clear();
  c.collision.radius = 0.001f;
  c.collision.mode = CollisionMode::Strands;
  // A strand that drapes, as soft as it can be without DFTL (B / (g L^3) = 1.2e-2 for the 13 cm
  // past the clamp, softHairDftl's 0): softer, its tip whips and can swing back into the bar
  // faster than the lists' margin allows for.
  c.sim.bendingStiffness = 2.5e-4f;
  c.sim.rootLength = 0.07f;  // holds the bar and the strand up to 1 cm before the bar
  return c;
}

// The same scene with the softer strand (B 1e-4, soft hair by softHairDftl's rule) that the
// scenes which need it to move fast keep: without contacts it falls through the bar within
// 0.5 s (the penalty scenes), and thrown it swings down past the margin in a frame.
inline Config softDrapeConfig() {
  Config c = drapeConfig();
  c.sim.bendingStiffness = 1e-4f;
  return c;
}

struct Drape {
  double distance = 0.0;  // closest distance between the strand and the bar
  double height = 0.0;    // height of the strand above the bar where it passes over it (x = 0,
                          // z = 0); -1 m when it no longer reaches the bar
};

// How the strand lies on the bar, from positions in the drape groom's layout.
inline Drape measureDrape(const std::vector<glm::vec4>& x) {
  Drape out{1e30, -1.0};
  for (uint32_t bar = 0; bar < 2; ++bar)
    for (uint32_t i = 3; i + 1 < x.size(); ++i) {
      double s, t;
      const glm::dvec3 p0(glm::vec3(x[bar])), p1(glm::vec3(x[bar + 1]));
      const glm::dvec3 q0(glm::vec3(x[i])), q1(glm::vec3(x[i + 1]));
      out.distance = std::min(out.distance, std::sqrt(closestSegmentPoints(p0, p1, q0, q1, s, t)));
    }
  // The first segment of the strand that reaches the bar's plane z = 0.
  for (uint32_t i = 3; i + 1 < x.size(); ++i)
    if (x[i].z < 0.0f && x[i + 1].z >= 0.0f) {
      const double t = -double(x[i].z) / double(x[i + 1].z - x[i].z);
      out.height = double(x[i].y) + t * double(x[i + 1].y - x[i].y) - double(x[1].y);
      break;
    }
  return out;
}

// The drape's bar, and its strand 5 mm along the bar and with its particles 5 mm along itself
// (so the two cross inside a segment of each: a skew pair keeps its side), to be thrown down
// at the bar (thrownConfig, throwDown) with gravity off.
inline Groom thrownGroom() {
  return drapeGroom(0.005f);
}

inline Config thrownConfig(int lists) {
  Config c = softDrapeConfig();
  c.collision.radius = 0.0005f;
  c.collision.lists = lists;
  c.sim.gravity = glm::vec3(0.0f);
  c.sim.damping = 0.0f;
  c.sim.substeps = 4;
  return c;
}

// The velocities that throw the strand of `x` (thrownGroom's layout) down at 0.3 m/s.
inline std::vector<glm::vec4> throwDown(const std::vector<glm::vec4>& x) {
  std::vector<glm::vec4> v(x.size(), glm::vec4(0.0f));
  for (size_t i = 3; i < x.size(); ++i) v[i].y = -0.3f;
  return v;
}

}  // namespace csm::test
