// The built-in mannequin: a neutral head, neck and shoulders (cranium, brow, open eyes with
// eyeballs and lids in their sockets, a nose with its bridge, wings and nostrils, a mouth at
// rest, cheekbones, jaw, chin, ears with rim and concha; an adult's neck, trapezius, shoulders
// and upper chest), smooth unions of distance primitives, in the head frame of docs/METHOD.md's
// units and conventions (y up, the face towards +z, the crown 0.1 m above the origin). Two
// rigid parts that meet in the neck: the head (cranium, face, upper neck) and the torso (lower
// neck, shoulders, upper chest); their necks cross at head.pivot's height, each ending inside
// the other, so that neither shows a cut as the head turns on the torso. Its fields and meshes
// are constants of the program, made once and shared read-only.
#pragma once

#include <glm/vec3.hpp>

#include "sim/head/distance_grid.h"
#include "sim/head/surface_mesh.h"

namespace csm {

// The head's part, the torso's, and the whole at rest (the nearer of the two).
double mannequinHeadDistance(const glm::dvec3& p);
double mannequinTorsoDistance(const glm::dvec3& p);
double mannequinDistance(const glm::dvec3& p);
// Each one's box and field sampled at 4 mm: the parts' for the collisions, the whole's for
// growing hair at rest.
const DistanceGrid& mannequinHeadGrid();
const DistanceGrid& mannequinTorsoGrid();
const DistanceGrid& mannequinGrid();
// Their surfaces (marching tetrahedra on the grid, vertices on the exact zero level, normals
// its gradient).
const SurfaceMesh& mannequinHeadMesh();
const SurfaceMesh& mannequinTorsoMesh();
const SurfaceMesh& mannequinMesh();
// Where the scalp is measured from on the mannequin: directions from here name scalp points.
inline constexpr glm::dvec3 kMannequinScalpCentre{0.0, 0.0, -0.008};

}  // namespace csm
