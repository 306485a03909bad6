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

enum class GroomFormat { Unknown, CyHair, TressFx, ObjCurves };

// cyHair files start with "HAIR"; TressFX text files (1.x, 2.x) with the word "version" or
// "numStrands"; binary TressFX files have no signature, so ".tfx" (any case) decides, as ".obj"
// does for OBJ curves. A ".hair" file without the signature is still CyHair, so its reader
// reports the bad signature rather than "unknown format".
GroomFormat detectGroomFormat(std::string_view path, std::span<const std::byte> bytes);

// Reads the file with the reader detectGroomFormat() picks; errors start with the path.
GroomReadResult readGroom(const std::string& path);

// True when `path` ends in `ext` (".obj"), in any case.
bool hasExtension(std::string_view path, std::string_view ext);
// The names writeGroom takes: ".hair" and ".obj", in any case.
bool isWritableGroomName(std::string_view path);

// Writes cyHair (.hair) or OBJ curves (.obj: writeObjCurves), atomically; other extensions are
// refused so a ".tfx" name never gets cyHair bytes.
bool writeGroom(const std::string& path, const Groom& groom, std::string* error = nullptr);

}  // namespace csm::io
