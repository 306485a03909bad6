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

// The parts of the face the renderer paints (render/head.frag: the eyes' white, iris and pupil,
// the lips' red), in the head frame, the right side (x > 0; the left mirrors it). The eye is
// sculpted from the same numbers: a ball with its cornea proud of it along the gaze (+z).
struct MannequinFace {
  glm::dvec3 eye;        // the right eyeball's centre
  double ball;           // its radius
  double corneaOffset;   // the cornea's centre, in front of the ball's along the gaze
  double cornea;         // the cornea's radius
  double iris, pupil;    // their radii across the gaze
  glm::dvec3 mouth;      // the middle of the line where the lips meet
  double lipsHalfWidth;  // the lips' red: half its width and half its height about that line
  double lipsHalfHeight;
};
inline constexpr MannequinFace kMannequinFace{
    {0.0315, -0.0135, 0.0595}, 0.0120, 0.0055, 0.0078, 0.0056, 0.0021,
    {0.0, -0.0790, 0.0890},    0.0225, 0.0085};

}  // namespace csm
