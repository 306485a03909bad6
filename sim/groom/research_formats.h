// The formats of the hair data sets that research trains and tests on, as the tools that convert
// between them (hairutil) read and write them:
//
//   USC-HairSalon .data (Hu et al. 2015; also Hair20K)   little-endian
//     int32 strand count, then per strand: int32 point count n, float32 xyz[n]
//     (a strand of one point marks a scalp sample without hair: dropped and counted)
//   CT2Hair .bin (Shen et al. 2023)                       little-endian
//     the same with seven float32 a point: xyz and four values csmhair does not use
//   strand PLY (hapPLY, as hairutil writes it)           ASCII, binary little or big endian
//     element vertex: x y z (any type, any order), red green blue (uchar 0-255, or a float
//     type 0-1) and thickness kept per strand (averaged); other properties passed over
//     element strand: nsegs (any integer type), a strand of nsegs + 1 consecutive vertices
//     or, without it, element edge: vertex1 vertex2 (or a vertex_indices list), chained
//
// Points are the data set's units and frame (millimetres, centimetres or metres; often the head
// mesh beside the hair in the same frame): the scene fits or places them (scene_groom.h). Errors
// name the byte (binary) or line (ASCII) of what is wrong.
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

// Floats a point: .data 3, .bin 7.
inline constexpr int kUscDataFloats = 3;
inline constexpr int kCt2HairFloats = 7;

// A strand-array file (.data or .bin) with `floats` a point, of which the first three are xyz.
GroomReadResult readStrandArrays(std::span<const std::byte> bytes, std::string_view name,
                                 int floats);
// The strands as such a file: the other floats of a point (.bin) are 0.
std::optional<std::vector<std::byte>> encodeStrandArrays(const Groom& groom, int floats,
                                                         std::string* error);

GroomReadResult readPlyStrands(std::span<const std::byte> bytes,
                               std::string_view name = "PLY strands");
// A strand PLY: vertex x y z (float), red green blue (uchar) and thickness (float) when the
// groom has them, strand nsegs (ushort, as hairutil writes it); binary little endian or ASCII.
std::optional<std::vector<std::byte>> encodePlyStrands(const Groom& groom, bool ascii,
                                                       std::string* error);

}  // namespace csm::io
