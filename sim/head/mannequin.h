// The built-in mannequin: a neutral head, neck and shoulders (cranium, brow, closed eyes with
// lids in their sockets, a nose with its bridge, wings and nostrils, lips, cheekbones, jaw,
// chin, ears with rim and concha), a smooth union of distance primitives, in the head frame of
// docs/METHOD.md's units and conventions (y up, the face towards +z, the crown 0.1 m above the
// origin). Its field and mesh are constants of the program, made once and shared read-only.
#pragma once

#include <glm/vec3.hpp>

#include "sim/head/distance_grid.h"
#include "sim/head/surface_mesh.h"

namespace csm {

double mannequinDistance(const glm::dvec3& p);
// The mannequin's box and its field sampled at 4 mm.
const DistanceGrid& mannequinGrid();
// Its surface (marching tetrahedra on mannequinGrid, vertices on the exact zero level, normals
// its gradient).
const SurfaceMesh& mannequinMesh();
// Where the scalp is measured from on the mannequin: directions from here name scalp points.
inline constexpr glm::dvec3 kMannequinScalpCentre{0.0, 0.0, -0.008};

}  // namespace csm
