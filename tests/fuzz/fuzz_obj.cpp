// libFuzzer target: text as an OBJ head (sim/head/obj_mesh.h's parseObjMesh, what head.mesh
// reads), and a mesh it accepts through what the scene makes of it (sim/head/head_model.h): its
// distance field, spheres fitted to it, the field's zero level.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <glm/common.hpp>

#include "sim/head/distance_grid.h"
#include "sim/head/surface_mesh.h"
#include "sim/head/sphere_fit.h"
#include "sim/head/mesh_field.h"
#include "sim/head/head_model.h"
#include "sim/head/obj_mesh.h"
#include "tests/fuzz/fuzz_common.h"

using csm::fuzz::fail;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const csm::io::ObjReadResult r = csm::io::parseObjMesh(text, "fuzz.obj");
  if (!r.mesh) {
    if (r.error.empty()) fail("parseObjMesh failed without a message");
    return 0;
  }
  const csm::SurfaceMesh& m = *r.mesh;
  if (m.indices.empty() || m.indices.size() % 3 != 0) fail("the mesh's indices are not triangles");
  if (m.normals.size() != m.positions.size()) fail("one normal a vertex");
  for (uint32_t i : m.indices)
    if (i >= m.positions.size()) fail("an index is out of range");
  for (const glm::vec3& n : m.normals)
    if (!std::isfinite(n.x + n.y + n.z)) fail("a normal is not finite");
  if (csm::openEdges(m) != 0) fail("the reader accepted an open surface");

  // The field as head.mesh gets it (loadHeadMesh: 4 mm cells, 2 cm margin), except that the
  // cell grows so that the grid has at most ~10 nodes an axis: the harness's cap, not the
  // product's, to keep one execution fast (a head-sized mesh at 4 mm is ~10^6 nodes).
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::vec3 span = hi - lo;
  const double extent = double(std::max({span.x, span.y, span.z})) + 0.04;
  const double cell = std::max(0.004, extent / 9.0);
  const csm::DistanceGrid g = csm::meshDistanceGrid(m, cell, 0.02);
  if (g.nodes.size() != size_t(g.dims.x) * g.dims.y * g.dims.z) fail("the field's node count");
  for (const glm::vec4& n : g.nodes)
    if (!std::isfinite(n.x + n.y + n.z + n.w)) fail("a node of the field is not finite");
  const std::vector<csm::Sphere> spheres = csm::fitSpheres(g, 2);
  for (const csm::Sphere& s : spheres)
    if (!std::isfinite(s.center.x + s.center.y + s.center.z) || !(s.radius > 0.0f))
      fail("a fitted sphere is not a ball");
  const csm::SurfaceMesh zero = csm::meshZeroLevel(g);
  if (zero.indices.size() % 3 != 0) fail("the zero level is not triangles");
  return 0;
}
