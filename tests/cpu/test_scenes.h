// Small scenes shared by the tests (the GPU suite runs the same against the CPU reference).
#pragma once

#include "sim/config.h"
#include "sim/groom.h"
#include "sim/hairstyle.h"

namespace csm::test {

// A few hundred strands of the default hairstyle: quick, but with every feature in play.
inline Config smallScene(int strands = 60) {
  Config c;
  c.hairstyle.strands = strands;
  c.hairstyle.particlesPerStrand = 0;
  c.hairstyle.minParticles = 6;
  c.hairstyle.maxParticles = 14;
  c.hairstyle.lengthMin = 0.12f;
  c.hairstyle.lengthMax = 0.25f;
  c.wind.strength = 0.0f;
  c.head.motion = HeadMotion::None;
  return c;
}

inline Groom growFor(const Config& c) {
  return growHairstyle(c.hairstyle, c.head.spheres, c.collision.radius);
}

}  // namespace csm::test
