// libFuzzer target: the research data sets' formats (sim/groom/research_formats.h) and PLY heads
// (sim/head/obj_mesh.h's parsePlyMesh). The first byte picks the reader: 0 USC-HairSalon .data,
// 1 CT2Hair .bin, 2 strand PLY, 3 a PLY head; the rest is the file. A groom accepted goes on
// through what a preset does with it (fuzz_groom.h); a head must be a closed surface.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "sim/groom/research_formats.h"
#include "sim/head/obj_mesh.h"
#include "sim/head/surface_mesh.h"
#include "tests/fuzz/fuzz_groom.h"

using csm::fuzz::fail;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const int reader = data[0] % 4;
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data + 1), size - 1);
  if (reader == 3) {
    const csm::io::ObjReadResult r = csm::io::parsePlyMesh(bytes, "fuzz.ply");
    if (!r.mesh) {
      if (r.error.empty()) fail("parsePlyMesh failed without a message");
      return 0;
    }
    const csm::SurfaceMesh& m = *r.mesh;
    if (m.indices.empty() || m.indices.size() % 3 != 0)
      fail("the mesh's indices are not triangles");
    for (uint32_t i : m.indices)
      if (i >= m.positions.size()) fail("an index is out of range");
    for (const glm::vec3& n : m.normals)
      if (!std::isfinite(n.x + n.y + n.z)) fail("a normal is not finite");
    if (csm::openEdges(m) != 0) fail("the reader accepted an open surface");
    return 0;
  }
  const csm::io::GroomReadResult r =
      reader == 2 ? csm::io::readPlyStrands(bytes, "fuzz.ply")
                  : csm::io::readStrandArrays(
                        bytes, reader == 0 ? "fuzz.data" : "fuzz.bin",
                        reader == 0 ? csm::io::kUscDataFloats : csm::io::kCt2HairFloats);
  if (!r.groom) {
    if (r.error.empty()) fail("a research reader failed without a message");
    return 0;
  }
  csm::fuzz::fitAsPreset(*r.groom, "fuzz.research", unsigned(size));
  return 0;
}
