// Accuracy measures of a hair state, the same for every solver.
#pragma once

#include <cstddef>
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

// Where a body has a torso: its field at its pose (with the head's), or which of the spheres
// are the torso's (those from headSpheres on).
struct BodyParts {
  PosedField torso;
  size_t headSpheres = SIZE_MAX;
};

// `pinned` root particles are kinematic and sit on the scalp: they are not counted as inside.
// The head is `field` where it has a grid (the mannequin), else the spheres; a particle inside
// the head counts there (headPenetrations), one inside the torso and not the head in
// torsoPenetrations.
Accuracy measureAccuracy(std::span<const glm::vec4> positions,
                         std::span<const glm::vec4> velocities, const Groom& groom,
                         std::span<const double> restLength, std::span<const Sphere> worldSpheres,
                         int pinned, const PosedField& field = {}, const BodyParts& parts = {});
// The same on a solver's own state: double precision, strand s being the particles
// [strandFirst[s], strandFirst[s+1]) with pinned[s] of them kinematic.
Accuracy measureAccuracy(std::span<const glm::dvec3> positions,
                         std::span<const glm::dvec3> velocities,
                         std::span<const uint32_t> strandFirst, std::span<const double> restLength,
                         std::span<const Sphere> worldSpheres, std::span<const int> pinned,
                         const PosedField& field = {}, const BodyParts& parts = {});

}  // namespace csm
