// Hair as curves in a Wavefront OBJ: the polylines a groom tool writes as `l` elements, chained
// into strands through the vertices they share. Blender 3.x turns particle hair into a mesh of
// edges and writes one `l i j` per edge; other tools write one `l` per strand (`l 1 2 3 ...`);
// both, and any mix, read to the same strands. `v` lines are positions (file units, fitted to
// the head like any groom); faces, normals, texture coordinates, groups and materials are
// passed over, so a head exported with its hair reads as its hair.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "sim/core/groom.h"
#include "sim/groom/read_common.h"

namespace csm::io {

// Reads the curves of an OBJ. A strand's first point is the end of its chain met first in the
// file; which end is the root is the scene's to decide once it knows the head (buildGroom
// turns a strand whose other end lies nearer the scalp). Refused with "name:line:": a vertex
// with three or more edges (a strand cannot branch), a closed loop, an `l` index that is 0 or
// out of range, a `v` line without three numbers, free-form curves (`cstype`, `curv`), no `l`
// element at all. Strands with a coordinate that is not finite, or no length, are dropped and
// counted (io/repair.h); an edge given twice, or from a vertex to itself, is read once.
GroomReadResult readObjCurves(std::span<const std::byte> bytes,
                              std::string_view name = "OBJ curves");
GroomReadResult readObjCurves(const std::string& path);

// The strands as OBJ curves, the form Blender 3.4 writes for hair converted to a mesh and the only
// one its importer reads as the strands: every point a `v` line (metres, y up, as the groom
// holds them; Blender's importer turns y up into its z up), then one `l i j` an edge, root to
// tip, strand after strand. readObjCurves reads it back to the same strands.
std::string encodeObjCurves(const Groom& groom);
// encodeObjCurves() written whole or not at all (path + ".tmp<pid>", then renamed over `path`).
bool writeObjCurves(const std::string& path, const Groom& groom, std::string* error = nullptr);

}  // namespace csm::io
