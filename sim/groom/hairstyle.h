// Grows strands from the scalp (the first head sphere), deterministically from a seed.
// Strand s depends only on the seed and s: a smaller strand count is a prefix of a larger one
// (as grown: hairstyle.separate_passes then moves the strands against each other).
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/head/distance_grid.h"
#include "sim/head/head_model.h"

namespace csm {

struct DistanceGrid;

// Particles of one strand chosen by its arc length (curl included), within the preset's bounds:
// the paper's 8-25.
int particlesForLength(const HairstyleConfig& h, double arcLength);

// Grows on the spheres (the first is the scalp), or, given a field, on its surface with roots
// seen from kMannequinScalpCentre (sim/head/mannequin.h), its hairline by `marks` (null: the
// mannequin's).
Groom growHairstyle(const HairstyleConfig& h, const std::vector<Sphere>& head,
                    float collisionRadius, const DistanceGrid* field = nullptr,
                    const ScalpMarks* marks = nullptr);

// The scene's hairstyle on the scene's head (its field when collision.head_shape is sdf).
Groom growHairstyle(const Config& c, const HeadModel& head);

// Whether hair grows in direction dir (a unit vector from the scalp's centre, head frame): the
// cap of hairstyle.scalp_angle about the crown, lower at the back than at the forehead, and on a
// field (`marks`: its brow and ears; null: the spheres) not over the ears.
bool onScalp(const HairstyleConfig& h, const glm::dvec3& dir, const ScalpMarks* marks);

}  // namespace csm
