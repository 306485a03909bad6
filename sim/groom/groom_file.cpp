#include "sim/groom/groom_file.h"

#include <algorithm>
#include <cctype>
#include <cstring>

#include "sim/groom/cyhair.h"
#include "sim/base/ply.h"
#include "sim/groom/obj_curves.h"
#include "sim/groom/research_formats.h"
#include "sim/groom/tressfx.h"
#include "sim/groom/tressfx_project.h"

namespace csm::io {

bool isWritableGroomName(std::string_view path) {
  for (const char* ext : {".hair", ".obj", ".data", ".bin", ".ply"})
    if (hasExtension(path, ext)) return true;
  return false;
}

GroomFormat detectGroomFormat(std::string_view path, std::span<const std::byte> bytes) {
  if (bytes.size() >= 4 && std::memcmp(bytes.data(), "HAIR", 4) == 0) return GroomFormat::CyHair;
  if (hasExtension(path, ".tfxproj")) return GroomFormat::TressFxProject;
  if (hasExtension(path, ".tfx") || isTressFxText(bytes)) return GroomFormat::TressFx;
  if (isPly(bytes)) return GroomFormat::PlyStrands;
  if (hasExtension(path, ".obj")) return GroomFormat::ObjCurves;
  if (hasExtension(path, ".data")) return GroomFormat::UscData;
  if (hasExtension(path, ".bin")) return GroomFormat::Ct2HairBin;
  if (hasExtension(path, ".ply")) return GroomFormat::PlyStrands;
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
      case GroomFormat::UscData:
        return readStrandArrays(bytes, name, kUscDataFloats);
      case GroomFormat::Ct2HairBin:
        return readStrandArrays(bytes, name, kCt2HairFloats);
      case GroomFormat::PlyStrands:
        return readPlyStrands(bytes, name);
      case GroomFormat::TressFxProject:
        return readTressFxProject(bytes, std::string(name));
      case GroomFormat::Unknown:
        break;
    }
    GroomReadResult result;
    result.error = std::string(name) +
                   ": unknown groom format; expected a cyHair file (signature \"HAIR\", .hair), "
                   "a TressFX file (.tfx, any version) or project (.tfxproj), OBJ curves (.obj), "
                   "USC-HairSalon strands (.data), "
                   "CT2Hair strands (.bin) or a strand PLY (.ply)";
    return result;
  });
}

bool writeGroom(const std::string& path, const Groom& groom, std::string* error) {
  if (hasExtension(path, ".obj")) return writeObjCurves(path, groom, error);
  if (hasExtension(path, ".hair")) return writeCyHair(path, groom, error);
  std::optional<std::vector<std::byte>> bytes;
  std::string problem;
  if (hasExtension(path, ".data"))
    bytes = encodeStrandArrays(groom, kUscDataFloats, &problem);
  else if (hasExtension(path, ".bin"))
    bytes = encodeStrandArrays(groom, kCt2HairFloats, &problem);
  else if (hasExtension(path, ".ply"))
    bytes = encodePlyStrands(
        groom, hasExtension(path, "_ascii.ply") || hasExtension(path, ".ascii.ply"), &problem);
  else {
    if (error)
      *error = path +
               ": can only write cyHair (.hair), OBJ curves (.obj), USC-HairSalon (.data), "
               "CT2Hair (.bin) and strand PLY (.ply) groom files";
    return false;
  }
  if (!bytes) {
    if (error) *error = path + ": " + problem;
    return false;
  }
  return detail::writeFileAtomically(path, *bytes, error);
}

}  // namespace csm::io
