// Cem Yuksel's cyHair ".hair" format (http://www.cemyuksel.com/research/hairmodels/,
// cyHairFile.h). All values little-endian:
//
//   byte   0  char     signature[4]    "HAIR"
//   byte   4  uint32   hair_count      strands
//   byte   8  uint32   point_count     points over all strands
//   byte  12  uint32   arrays          bit flags: 1 segments, 2 points, 4 thickness,
//                                      8 transparency, 16 colors
//   byte  16  uint32   d_segments      segments per strand when there is no segments array
//   byte  20  float    d_thickness     defaults for the absent per-point arrays
//   byte  24  float    d_transparency
//   byte  28  float    d_color[3]
//   byte  40  char     info[88]        free text
//   byte 128  the arrays whose bit is set, in this order, tightly packed:
//             segments      uint16[hair_count]    a strand has segments + 1 points
//             points        float[3 * point_count]
//             thickness     float[point_count]
//             transparency  float[point_count]
//             colors        float[3 * point_count]
//
// Units are whatever the exporter used (often centimetres); fitToHead() brings them to
// metres. The file has no up axis; most published models are y-up.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sim/core/groom.h"
#include "sim/groom/read_common.h"

namespace csm::io {

inline constexpr size_t kCyHairHeaderBytes = 128;

// Reads a cyHair file. Per-point thickness and colour become per-strand values by
// averaging the strand's points (thickness in file units, colour clamped to 0..1); the
// Groom's thickness/color stay empty when the file has no such array (the header's
// defaults are usually placeholders). Transparency is checked but not kept.
// Malformed data yields an error naming the byte offset; nothing is allocated before the
// header's counts have been checked against the data size.
GroomReadResult readCyHair(std::span<const std::byte> bytes, std::string_view name = "cyHair data");
GroomReadResult readCyHair(const std::string& path);

// Encodes `groom` as a cyHair file: segments and points always, thickness and colors when
// the groom has them (repeated on each point of the strand). Fails (nullopt, *error set)
// for a structurally broken groom, non-finite points or a strand of more than 65536 points.
std::optional<std::vector<std::byte>> encodeCyHair(const Groom& groom, std::string* error);

// encodeCyHair() written to path + ".tmp<pid>", then renamed over `path`.
bool writeCyHair(const std::string& path, const Groom& groom, std::string* error = nullptr);

}  // namespace csm::io
