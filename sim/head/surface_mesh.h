// A closed triangle surface: what the renderer draws of the head, and how a distance grid's zero
// level becomes one (marching tetrahedra).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/head/distance_grid.h"

namespace csm {

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

// A coarser mesh of about `triangles` triangles (the mesh itself when it has no more), for
// drawing at interactive quality: vertices merged by cell of a grid (vertex clustering; cells
// sized from the mean edge), each cell's vertices at their mean with their normals' mean, the
// triangles that collapse dropped. The surface moves by at most about a cell.
SurfaceMesh coarserMesh(const SurfaceMesh& m, size_t triangles);

// Triangles facing against the mean of their vertices' normals: where marching tetrahedra meet
// a crease or a saddle finer than their grid, vertices projected onto the zero level can fold a
// triangle over, which draws as a dark speck.
size_t foldedTriangles(const SurfaceMesh& m);

// Unfolds them: each vertex of a folded triangle, and its neighbours, moved to its neighbours'
// mean and projected back onto `exact`'s zero level (its normal the gradient there), `rounds`
// times or until none is folded. Returns the folded triangles left.
size_t relaxFolds(SurfaceMesh& m, const DistanceFunction& exact, int rounds = 6);

// Edges of a mesh used other than once in each direction (0 for a closed, consistently
// oriented surface).
size_t openEdges(const SurfaceMesh& m);

// Closes each hole of a consistently oriented surface (a scan open at the neck): a boundary loop
// (edges met in one direction only, each vertex on it starting one) gets a fan of triangles to a
// new vertex at the loop's mean, turned as its neighbours are. Returns the holes capped (their
// centres in `centres` when given); a boundary that is not a set of simple loops (two loops
// through one vertex) is left as it is.
size_t capHoles(SurfaceMesh& m, std::vector<glm::vec3>* centres = nullptr);

}  // namespace csm
