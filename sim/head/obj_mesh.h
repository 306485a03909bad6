// A head read from a Wavefront OBJ or a PLY (head.mesh): the closed triangle surface that the hair
// meets and that is drawn. OBJ is parsed by tinyobjloader after our own pass over the lines, which
// names the file and the line of anything the mesh cannot be used with; PLY (ASCII or binary, as
// scans and research data sets ship their heads) by sim/base/ply.h, naming the face and its byte
// or line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/head/surface_mesh.h"

namespace csm::io {

struct ObjReadResult {
  std::optional<SurfaceMesh> mesh;  // set on success
  std::string error;                // "path:line: message" or "path: message" on failure
  size_t cappedHoles = 0;           // holes closed (a scan open at the neck: capHoles)
  std::vector<glm::vec3> holes;     // their centres, in the file's units
};

// Reads the OBJ at `path` as a closed surface, in the file's units and axes (the scene brings it
// into the head frame: sim/head/head_fit.h). Polygons are split into fans; vertices at the same
// position are merged (exporters split them at texture seams); the surface is turned outwards when
// it faces in; normals are the angle-weighted normals of the triangles (the file's are not used);
// each hole is capped (a scan open at the neck collides as if closed there). CRLF line ends, NUL
// padding after the last line (as ZBrush writes), `mtllib`, `usemtl`, `vt`, `vn`, `s`, `g` and `o`
// lines, quads, n-gons and negative indices are read. Refused: a missing file; a vertex coordinate
// that is not a finite number; a NUL byte before the last line; a face with fewer than three
// vertices or an index out of range (0, or beyond the vertices); no vertices; no faces; a surface
// that is not consistently oriented or whose holes do not close (an open surface has no inside to
// give the field its sign).
ObjReadResult readObjMesh(const std::string& path);
// The same from the file's text in memory; `name` stands for the path in messages.
ObjReadResult parseObjMesh(std::string_view text, const std::string& name);
// A PLY head: element vertex (x y z), element face (a list vertex_indices, or vertex_index),
// checked and closed as an OBJ is.
ObjReadResult parsePlyMesh(std::span<const std::byte> bytes, const std::string& name);
// head.mesh by its content: PLY when it starts as one, else OBJ.
ObjReadResult readHeadMeshFile(const std::string& path);
// What every head mesh gets once its polygons are triangles (indices into `positions`, each
// triangle's place in the file in `triangleWhere`, ":15" or ": face 3 (byte 120)"): positions
// welded, triangles without area dropped, holes capped, then the checks above and the normals.
ObjReadResult finishHeadMesh(std::vector<glm::vec3> positions,
                             const std::vector<uint32_t>& triangles,
                             const std::vector<std::string>& triangleWhere,
                             const std::string& path);

}  // namespace csm::io
