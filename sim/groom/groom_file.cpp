#include "sim/groom/groom_file.h"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "sim/groom/cyhair.h"
#include "sim/groom/obj_curves.h"
#include "sim/groom/tressfx.h"

namespace csm::io {

bool hasExtension(std::string_view path, std::string_view ext) {
  if (path.size() < ext.size()) return false;
  return std::equal(ext.begin(), ext.end(), path.end() - ext.size(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) ==
           std::tolower(static_cast<unsigned char>(b));
  });
}

bool isWritableGroomName(std::string_view path) {
  return hasExtension(path, ".hair") || hasExtension(path, ".obj");
}

GroomFormat detectGroomFormat(std::string_view path, std::span<const std::byte> bytes) {
  if (bytes.size() >= 4 && std::memcmp(bytes.data(), "HAIR", 4) == 0) return GroomFormat::CyHair;
  if (hasExtension(path, ".tfx") || isTressFxText(bytes)) return GroomFormat::TressFx;
  if (hasExtension(path, ".obj")) return GroomFormat::ObjCurves;
  if (hasExtension(path, ".hair")) return GroomFormat::CyHair;
  return GroomFormat::Unknown;
}

GroomReadResult readGroom(const std::string& path) {
  return detail::readGroomFile(path, [](std::span<const std::byte> bytes, std::string_view name) {
    switch (detectGroomFormat(name, bytes)) {
      case GroomFormat::CyHair:
        return readCyHair(bytes, name);
      case GroomFormat::TressFx:
        return readTressFx(bytes, name);
      case GroomFormat::ObjCurves:
        return readObjCurves(bytes, name);
      case GroomFormat::Unknown:
        break;
    }
    GroomReadResult result;
    result.error = std::string(name) +
                   ": unknown groom format; expected a cyHair file (signature \"HAIR\", .hair), "
                   "a TressFX file (.tfx, any version) or OBJ curves (.obj)";
    return result;
  });
}

bool writeGroom(const std::string& path, const Groom& groom, std::string* error) {
  if (hasExtension(path, ".obj")) return writeObjCurves(path, groom, error);
  if (!hasExtension(path, ".hair")) {
    if (error) *error = path + ": can only write cyHair groom files (.hair) and OBJ curves (.obj)";
    return false;
  }
  return writeCyHair(path, groom, error);
}

}  // namespace csm::io
