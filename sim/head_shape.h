// The head's shape as the hair meets it: a signed distance field sampled on a grid in the
// head's frame (negative inside), read by trilinear interpolation with the gradient as the
// normal; the built-in mannequin that fills it; and the closed surface mesh drawn from it.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "sim/config.h"
#include "sim/head.h"

namespace csm {

// A distance field on the nodes of a regular grid. Each node holds the gradient (xyz) and the
// distance (w), so one trilinear read gives both, and the normal turns smoothly across cells.
struct DistanceGrid {
  glm::vec3 origin{0.0f};        // the lowest node (m)
  float cell = 0.0f;             // node spacing (m)
  glm::ivec3 dims{0};            // nodes per axis
  std::vector<glm::vec4> nodes;  // x fastest, then y, then z

  bool empty() const { return nodes.empty(); }
  size_t index(int i, int j, int k) const {
    return size_t(i) + size_t(dims.x) * (size_t(j) + size_t(dims.y) * size_t(k));
  }
  // Distance at p (trilinear), and the interpolated gradient when asked (not normalised). Far
  // outside the grid the distance is to the grid's box, whose border lies outside the shape.
  double sample(const glm::dvec3& p, glm::dvec3* gradient = nullptr) const;
};

// A signed distance function: negative inside, about the distance to the surface near it.
using DistanceFunction = std::function<double(const glm::dvec3&)>;

// Samples f on the nodes of the box [lo, hi] spaced `cell`, gradients by central differences.
DistanceGrid sampleDistance(const DistanceFunction& f, const glm::dvec3& lo, const glm::dvec3& hi,
                            double cell);

// The built-in mannequin: a neutral head, neck and shoulders (cranium, brow, eye sockets,
// nose, cheeks, jaw, chin, ears), a smooth union of distance primitives, in the head frame of
// DESIGN.md section 3 (y up, the face towards +z, the crown 0.1 m above the origin).
double mannequinDistance(const glm::dvec3& p);
// The mannequin's box and its field sampled at 4 mm: made once, shared (read-only).
const DistanceGrid& mannequinGrid();
// Where the scalp is measured from on the mannequin: directions from here name scalp points.
inline constexpr glm::dvec3 kMannequinScalpCentre{0.0, 0.0, -0.008};

// The head the scene collides with and draws: the field of head.mesh or else the mannequin's
// when collision.head_shape is sdf; no field (spheres) otherwise.
const DistanceGrid* headField(const Config& c);
// The field of the head's shape whatever collision.head_shape says: head.mesh's, or the
// mannequin's.
const DistanceGrid& headShapeField(const Config& c);

// `count` spheres inside the field's shape, centres on the plane x = 0 (the head is symmetric
// about it), searched on the field's nodes in y and z, each as large as fits there (radius =
// -distance at its centre, less what its surface still pokes out where the field is not an
// exact distance): first the largest, then each the one that covers the most field nodes
// (every second one) inside the shape not yet covered. Only the head above y = -0.2 m
// counts and holds centres, so the shoulders take none. Deterministic.
std::vector<Sphere> fitSpheres(const DistanceGrid& g, int count);

// The spheres the scene collides with, grows hair from and draws when collision.head_shape is
// spheres: head.spheres, or as many fitted to headShapeField (made once per field and count)
// when head.fit_spheres is set.
const std::vector<Sphere>& headSpheres(const Config& c);

// What a solver collides with, resolved once when its scene is set (headField and headSpheres
// look a loaded mesh or fitted spheres up by path and under a lock): read every step.
struct SceneHead {
  const DistanceGrid* field = nullptr;  // null: the spheres
  std::vector<Sphere> spheres;          // head frame
};
inline SceneHead sceneHead(const Config& c) {
  return {headField(c), headSpheres(c)};
}

// A field placed in the world by the head's pose: the head a measure counts particles in.
struct PosedField {
  const DistanceGrid* grid = nullptr;
  Pose pose;
  // Whether a world point lies inside the surface.
  bool contains(const glm::dvec3& world) const;
};

// Moves p (head frame) out of the field's surface inflated by `radius`; true when it moved.
// `normal` gets the outward direction there, `distance` the field's distance where p is left
// (its last read).
bool pushOutOfField(const DistanceGrid& g, glm::dvec3& p, double radius,
                    glm::dvec3* normal = nullptr, double* distance = nullptr);

// Projects p onto the zero level of the field along its gradient (a few Newton steps).
glm::dvec3 projectToSurface(const DistanceGrid& g, glm::dvec3 p);

// The point where the ray from `from` along unit `dir` first leaves the shape, searched from
// outside inwards (the ray starts inside); used to put roots on the scalp.
glm::dvec3 surfaceAlong(const DistanceGrid& g, const glm::dvec3& from, const glm::dvec3& dir);

// A triangle mesh, counter-clockwise seen from outside.
struct SurfaceMesh {
  std::vector<glm::vec3> positions, normals;
  std::vector<uint32_t> indices;
};
// The zero level of the grid by marching tetrahedra (six per cell, one diagonal, so that
// neighbouring cells cut their shared faces alike): closed when the grid's border nodes lie
// outside. With `exact`, vertices are moved onto its zero level and take its gradient as the
// normal; otherwise the grid's.
SurfaceMesh meshZeroLevel(const DistanceGrid& g, const DistanceFunction& exact = {});
// The mannequin's mesh, made once.
const SurfaceMesh& mannequinMesh();

// The surface drawn for the scene's head: head.mesh's or the mannequin's when
// collision.head_shape is sdf; none (spheres) otherwise.
const SurfaceMesh* headSurface(const Config& c);

// The signed distance to a closed, outward-facing triangle mesh, sampled on the nodes of its
// box grown by `margin`, spaced `cell`: exact distances near the surface, the nearest
// triangle carried outwards from there (Tsai 2002's closest point sweeping), the sign by the
// parity of crossings along each row of nodes; the gradient points away from the nearest point.
DistanceGrid meshDistanceGrid(const SurfaceMesh& m, double cell, double margin);

// A head read from an OBJ (head.mesh) and its field (4 mm, a 2 cm margin).
struct LoadedHead {
  SurfaceMesh mesh;
  DistanceGrid grid;
};
// Reads, checks and samples the OBJ at `path` once per process; later calls share it (the
// solvers and the renderer). nullptr with a message naming the file and line on failure.
const LoadedHead* loadHeadMesh(const std::string& path, std::string* error);
// head.mesh resolved against the folder of the preset it came from (empty: the mannequin).
std::string headMeshPath(const Config& c);

// Edges of a mesh used other than once in each direction (0 for a closed, consistently
// oriented surface).
size_t openEdges(const SurfaceMesh& m);

}  // namespace csm
