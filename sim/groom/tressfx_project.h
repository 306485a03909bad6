// AMD TressFX projects (.tfxproj, as the TressFX viewer and Maya exporter write them): a text
// file naming the groom's pieces, each with its follow hairs and simulation file, then the
// project's settings and collision shapes:
//
//   version 3.0
//   project_name ponytail
//   front_top.tfx 4 0.5 1 front_top.tfxsim Front      piece, follow hairs a guide, their radius,
//   back.tfx 2 0.4 1 back.tfxsim Back                  tip separation, .tfxsim, GUI section
//   ponytail.sdkmesh                                   the mesh, animation, skin, texture
//   lengthConstraintIterations 3                       settings: windMag, thickness, Kd, ...
//   collision_sphere x y z r                           in the files' units
//   collision_capsule x0 y0 z0 x1 y1 z1 r
//
// A `#` in the first column starts a comment. Paths are relative to the project's folder.
#pragma once

#include <span>
#include <string>

#include "sim/groom/read_common.h"

namespace csm::io {

// More follow hairs a guide than this is taken for a corrupt line (TressFX's own tools go to 16).
inline constexpr uint32_t kMaxFollowHairs = 64;

// The project as one groom: every piece's strands (TressFX, any version, read with
// readTressFx) in the project's order, in one frame, so that the scene fits them together; the
// pieces' held tips kept, each strand's follow hairs (its piece's count, radius and tip
// separation: Groom::follow) and the collision spheres (GroomReadResult::spheres, in the files'
// units). What csmhair does not use (the .tfxsim values; capsules; the meshes, textures and
// settings) is listed in GroomReadResult::unused. Errors name the project's line, then the
// piece's own error.
GroomReadResult readTressFxProject(std::span<const std::byte> bytes, const std::string& path);

}  // namespace csm::io
