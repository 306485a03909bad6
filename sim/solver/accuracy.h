// Accuracy measures of a hair state, the same for every solver.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "sim/core/config.h"
#include "sim/core/results.h"
#include "sim/core/groom.h"
#include "sim/head/distance_grid.h"

namespace csm {

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
