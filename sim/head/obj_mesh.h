// A head read from a Wavefront OBJ (head.mesh): the closed triangle surface that the hair meets
// and that is drawn. Parsed by tinyobjloader after our own pass over the lines, which names the
// file and the line of anything the mesh cannot be used with.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "sim/head/surface_mesh.h"

namespace csm::io {

struct ObjReadResult {
  std::optional<SurfaceMesh> mesh;  // set on success
  std::string error;                // "path:line: message" or "path: message" on failure
};

// Reads the OBJ at `path` as a closed surface in metres, in the head frame (METHOD.md
// section 9). Polygons are split into fans; vertices at the same position are merged (exporters
// split them at texture seams); the surface is turned outwards when it faces in; normals are
// the angle-weighted normals of the triangles (the file's are not used). Refused: a missing
// file; a vertex coordinate that is not a finite number; a face with fewer than three vertices
// or an index out of range (0, or beyond the vertices); no vertices; no faces; a surface that is
// not closed and consistently oriented (an open surface has no inside to give the field its
// sign); a mesh over 1 m across (not in metres).
ObjReadResult readObjMesh(const std::string& path);
// The same from the file's text in memory; `name` stands for the path in messages.
ObjReadResult parseObjMesh(std::string_view text, const std::string& name);

}  // namespace csm::io
