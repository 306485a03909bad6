// Small generated scenes for the tests and the benchmarks: a few strands to a few hundred of
// the default hairstyle, particle counts following length within the caller's bounds, still air
// and a still head unless the caller moves them. One builder, so that a scene two tests share
// (the GPU suite runs the CPU's scenes) is one call and not two copies of its fields.
#pragma once

#include "sim/core/config.h"

namespace csm {

struct SmallScene {
  int strands = 60;
  int minParticles = 6;
  int maxParticles = 14;
  float lengthMin = 0.12f;  // m
  float lengthMax = 0.25f;  // m
};

inline Config smallSceneConfig(const SmallScene& s) {
  Config c;
  c.hairstyle.strands = s.strands;
  c.hairstyle.particlesPerStrand = 0;
  c.hairstyle.minParticles = s.minParticles;
  c.hairstyle.maxParticles = s.maxParticles;
  c.hairstyle.lengthMin = s.lengthMin;
  c.hairstyle.lengthMax = s.lengthMax;
  c.wind.strength = 0.0f;
  c.head.motion = HeadMotion::None;
  return c;
}

// Strands shaken through each other, thick (r = 2 mm) and in a thicker layer over the scalp than
// the default's 6 mm, or the groom lies packed with pairs closer than r that no solver can undo:
// hair-hair collision's test scene on both solvers.
inline Config shakenCurtainsConfig() {
  Config c = smallSceneConfig({.strands = 600, .lengthMin = 0.2f, .lengthMax = 0.3f});
  c.wind.strength = 3.0f;
  c.head.motion = HeadMotion::Shake;
  c.head.amplitude = 40.0f;
  c.collision.radius = 0.002f;
  c.hairstyle.volume = 0.03f;
  return c;
}

}  // namespace csm
