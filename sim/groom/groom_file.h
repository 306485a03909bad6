// One entry point for groom files, whatever their format: the app and the presets name a
// file, this picks the reader by signature, then by extension.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "sim/core/groom.h"
#include "sim/groom/read_common.h"

namespace csm::io {

enum class GroomFormat {
  Unknown,
  CyHair,
  TressFx,
  ObjCurves,
  UscData,
  Ct2HairBin,
  PlyStrands,
  TressFxProject
};

// cyHair files start with "HAIR"; TressFX text files (1.x, 2.x) with the word "version" or
// "numStrands"; binary TressFX files have no signature, so ".tfx" (any case) decides, as ".obj"
// does for OBJ curves. A ".hair" file without the signature is still CyHair, so its reader
// reports the bad signature rather than "unknown format". PLY files start with "ply" (strands:
// research_formats.h); USC-HairSalon's ".data" and CT2Hair's ".bin" have no signature.
GroomFormat detectGroomFormat(std::string_view path, std::span<const std::byte> bytes);

// Reads the file with the reader detectGroomFormat() picks; errors start with the path.
GroomReadResult readGroom(const std::string& path);

// The names writeGroom takes: ".hair", ".obj", ".data", ".bin" and ".ply", in any case.
bool isWritableGroomName(std::string_view path);

// Writes by the name's extension, atomically: cyHair (.hair), OBJ curves (.obj:
// writeObjCurves), USC-HairSalon (.data), CT2Hair (.bin), strand PLY (.ply: binary little
// endian; a name ending in "_ascii.ply" or ".ascii.ply" gets ASCII). Other extensions are
// refused so a ".tfx" name never gets cyHair bytes.
bool writeGroom(const std::string& path, const Groom& groom, std::string* error = nullptr);

}  // namespace csm::io
