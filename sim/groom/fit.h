// Fitting a groom read from a file onto the simulation's head: files come in arbitrary
// units (centimetres, or normalised to unit size) and placements; the solver wants metres
// with the roots on the head spheres (METHOD.md §9: y up, head ~0.1 m in radius).
#pragma once

#include <cstddef>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/head/distance_grid.h"

namespace csm::io {

// The head's spheres (centre, radius; head-local metres) are csm::Sphere from the scene
// configuration, so a preset's head can be passed straight in.
using Sphere = csm::Sphere;

struct FitOptions {
  // Uniform scale from file units to metres; 0 = automatic when autoFit is on, else 1.
  float scale = 0.0f;
  // Rotation in degrees, applied to the file's points about the world axes in the order
  // X, then Y, then Z (R = Rz * Ry * Rx), before scaling.
  glm::vec3 rotationDeg{0.0f};
  // Translation in metres, added last (after the automatic placement, as a correction).
  glm::vec3 offset{0.0f};
  // Scale so the roots' bounding sphere has the radius of the largest head sphere, and
  // place that bounding sphere's centre on the head sphere's centre.
  bool autoFit = true;
  // Head spheres; autoFit uses the largest. Empty: a 0.1 m sphere at the origin.
  std::vector<Sphere> headSpheres;
  // Afterwards, move each strand rigidly so its root lies on the surface of the nearest
  // head sphere (along that sphere's normal through the root); the strand keeps its shape.
  // Surface points buried inside another sphere are passed over while others exist.
  bool snapRoots = false;
  // With a field (the mannequin, sim/head/mannequin.h), roots snap to its nearest surface point
  // instead of the spheres'.
  const DistanceGrid* headField = nullptr;
};

// What fitToHead() did, for logs and the UI.
struct FitReport {
  float scale = 1.0f;               // the scale applied (automatic or given)
  glm::mat3 rotation{1.0f};         // import_rotation's
  glm::vec3 translation{0.0f};      // added after rotation and scale, offset included
  float rootBoundingRadius = 0.0f;  // roots' bounding sphere before scaling, file units
  size_t snappedStrands = 0;        // strands moved by snapRoots
  float maxSnapDistance = 0.0f;     // the largest such move, metres
  // A point of the file (in its units, before the fit) where the fit put the groom's: for what
  // comes in the groom's frame beside it (a TressFX project's collision spheres).
  glm::vec3 apply(const glm::vec3& p) const { return scale * (rotation * p) + translation; }
};

// Transforms every point: p' = scale * R * p + translation, then snaps roots if asked.
// Per-strand thickness is scaled with the points (both are in file units before).
// With autoFit and fewer than two distinct roots the scale cannot be inferred: 1 is used
// unless `scale` is given.
FitReport fitToHead(Groom& groom, const FitOptions& options);

// The smallest sphere containing all points (Welzl 1991, iterative form, in double).
// Exposed for tests and tools; empty input gives a zero sphere at the origin.
Sphere boundingSphere(const std::vector<glm::vec3>& points);

}  // namespace csm::io
