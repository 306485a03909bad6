// The signed distance field of a closed triangle mesh (head.mesh).
#pragma once

#include "sim/head/distance_grid.h"
#include "sim/head/surface_mesh.h"

namespace csm {

// The signed distance to a closed, outward-facing triangle mesh, sampled on the nodes of its
// box grown by `margin`, spaced `cell`: exact distances near the surface, the nearest
// triangle carried outwards from there (Tsai 2002's closest point sweeping), the sign by the
// parity of crossings along each row of nodes; the gradient points away from the nearest point.
DistanceGrid meshDistanceGrid(const SurfaceMesh& m, double cell, double margin);

}  // namespace csm
