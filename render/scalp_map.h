// Where hair grows on each head sphere, as a texture the head shader paints the scalp from:
// the gaps between strands then show hair-coloured scalp rather than bare skin, as on a real
// head.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "gl/texture.h"
#include "sim/core/groom.h"
#include "sim/head/head_model.h"

namespace csm {

// Octahedral mapping of a unit vector to [0,1]^2 (Cigolle et al. 2014): no poles, so the
// crown and the back of the head get texels like everywhere else. head.frag mirrors it.
glm::vec2 octahedral(glm::vec3 d);

struct ScalpTexels {
  int size = 0, layers = 0;
  std::vector<std::uint8_t> rgba;  // layer-major, rows of `size`: root colour, coverage
  std::vector<float> coverage;     // the same texels' coverage, 0..1, before rounding
};
// The roots binned per sphere (the nearest one within 2 cm), blurred over their typical spacing
// (8 mm at least) into a density of drawn strands a square metre (`strandsPerRoot` of them a
// root: 1 + the children drawn about each), and that density as the share of the scalp the hair
// covers: 1 - exp(-density / 15 a cm^2). A dense groom covers its scalp and fades at its
// hairline; a sparse one (100 strands, the guides alone) darkens it a little and evenly.
ScalpTexels scalpTexels(const Groom& groom, const std::vector<Sphere>& spheres,
                        float strandsPerRoot = 1.0f);
// The spheres the scalp map is laid over: the scene's, or for the mannequin one about its
// scalp centre (its roots lie 0.07-0.1 m from it, within the 2 cm that counts as on it).
std::vector<Sphere> scalpSpheres(const HeadModel& head);
// An RGBA8 2D array, one layer per sphere.
gl::Texture makeScalpMap(const Groom& groom, const std::vector<Sphere>& spheres,
                         float strandsPerRoot);

}  // namespace csm
