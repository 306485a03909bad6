// Spheres fitted inside a head's field, for collision.head_shape spheres with head.fit_spheres.
#pragma once

#include <vector>

#include "sim/core/config.h"
#include "sim/head/distance_grid.h"

namespace csm {

// `count` spheres inside the field's shape, centres on the plane x = 0 (the head is symmetric
// about it), searched on the field's nodes in y and z, each as large as fits there (radius =
// -distance at its centre, less what its surface still pokes out where the field is not an
// exact distance): first the largest, then each the one that covers the most field nodes
// (every second one) inside the shape not yet covered. Only the head above y = -0.2 m
// counts and holds centres, so the shoulders take none. Deterministic.
std::vector<Sphere> fitSpheres(const DistanceGrid& g, int count);

}  // namespace csm
