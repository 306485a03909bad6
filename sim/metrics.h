// Accuracy measures of a hair state, the same for every solver.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "sim/config.h"
#include "sim/groom.h"
#include "sim/head_shape.h"

namespace csm {

struct Accuracy {
  double maxStrain = 0.0;         // largest relative stretch |x_i+1 - x_i| / l_i - 1 (0 = rest)
  double meanStrain = 0.0;        // mean of |relative stretch| over segments
  uint64_t headPenetrations = 0;  // free particles inside the head (its field or a sphere)
  double maxSpeed = 0.0;          // m/s
  uint64_t nanCount = 0;          // particles with a non-finite position or velocity
};

// Rest length of every segment i -> i+1 of the groom (0 after a strand's last particle).
std::vector<double> restLengths(const Groom& groom);

// `pinned` root particles are kinematic and sit on the scalp: they are not counted as inside.
// The head is `field` where it has a grid (the mannequin), else the spheres.
Accuracy measureAccuracy(std::span<const glm::vec4> positions,
                         std::span<const glm::vec4> velocities, const Groom& groom,
                         std::span<const double> restLength, std::span<const Sphere> worldSpheres,
                         int pinned, const PosedField& field = {});
// The same on a solver's own state: double precision, strand s being the particles
// [strandFirst[s], strandFirst[s+1]) with pinned[s] of them kinematic.
Accuracy measureAccuracy(std::span<const glm::dvec3> positions,
                         std::span<const glm::dvec3> velocities,
                         std::span<const uint32_t> strandFirst, std::span<const double> restLength,
                         std::span<const Sphere> worldSpheres, std::span<const int> pinned,
                         const PosedField& field = {});

}  // namespace csm
