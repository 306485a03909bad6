// AMD TressFX ".tfx" files, every version, told apart by their first bytes:
//
// TressFX 1.x and 2.x (text; TressFX 1.0 has no version line): keywords, then the strands,
//   version 2.0                                   optional
//   scale 1 / rotation x y z / translation x y z  2.x: applied as the AMD loader does
//                                                 (scaled, turned by Ry Rx Rz, radians, moved)
//   bothEndsImmovable 0                           1: the head holds each strand's tip too
//   maxNumVerticesInStrand, numFollowHairsPerGuideHair, maxRadiusAroundGuideHair: not needed
//   numStrands N
//   is sorted 1                                   optional
//   strand 0 numVerts 16 texcoord u v             then one "x y z" line a vertex
//
// TressFX 3.x (binary, version 3.0 <= v < 4.0; TressFXFileFormat.h, TressFXFileObject), 296
// bytes of header, all values little-endian:
//   byte   0  float   version
//   byte   4  uint32  numGuideHairStrands
//   byte   8  uint32  numVerticesPerStrand      the same for every strand
//   byte  12  uint32  numFollowHairsPerGuideHair  follow hairs made at run time: not read
//   byte  16  bool    bothEndsImmovable         non-zero: the head holds each strand's tip too
//   byte  20  uint32  reserved1[31]
//   byte 144  uint32  verticesOffset            float3[strands * vertices]
//   byte 148  uint32  perStrandThicknessOffset  float[strands]
//   byte 152  uint32  perStrandTexCoordOffset   float2[strands]
//   byte 156  uint32  perVertexColorOffset      float4[strands * vertices]
//   byte 160  uint32  guideHairStrandOffset     uint32[strands]
//   byte 164  uint32  perVertexTexCoordOffset   float2[strands * vertices]
//   byte 168  uint32  reserved2[32]
//
// TressFX 4.x (binary, any other version; TressFXTFXFileHeader), 160 bytes of header:
//   byte   0  float   version                 4.0 from AMD's exporters
//   byte   4  uint32  numHairStrands
//   byte   8  uint32  numVerticesPerStrand    the same for every strand (AMD: 4..64, pow2)
//   byte  12  uint32  offsetVertexPosition    float4[strands * vertices]: xyz, w = inverse
//                                             mass (0 = pinned): a strand whose last w
//                                             is 0 has its tip held by the head (unless
//                                             every w of the file is 0: no masses)
//   byte  16  uint32  offsetStrandUV          float2[strands]
//   byte  20  uint32  offsetVertexUV          float2[strands * vertices]
//   byte  24  uint32  offsetStrandThickness   float[strands]
//   byte  28  uint32  offsetVertexColor       float4[strands * vertices]
//   byte  32  uint32  reserved[32]
//
// Binary offsets are absolute byte positions in the file; 0 means the array is absent
// (positions must be present). There is no signature: ".tfx" names the format, the text form
// starts with "version" or "numStrands", and the version float picks the binary layout.
// AMD's Maya exporter writes positions (in scene units, usually centimetres) and optionally
// strand UVs only; thickness and colours come from other tools.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "sim/groom/read_common.h"

namespace csm::io {

inline constexpr size_t kTressFx3HeaderBytes = 296;
inline constexpr size_t kTressFxHeaderBytes = 160;  // 4.x

// Reads a .tfx file of any version into a Groom. Per-strand thickness is kept as written (file
// units, as for cyHair); per-vertex colours are averaged over the strand (rgb, clamped to 0..1;
// alpha dropped). UVs and guide flags are bounds-checked but not kept. Errors name the byte
// offset (binary) or the line (text); the flaws io/repair.h repairs are repaired and counted.
// Every version is read as AMD's tools write it, in DirectX's left-handed axes with the face
// toward -z (GroomReadResult::facesMinusZ): the scene mirrors z into the head frame.
GroomReadResult readTressFx(std::span<const std::byte> bytes,
                            std::string_view name = "TressFX data");
// The same without the facing said (what the layout alone gives).
GroomReadResult readTressFxLayout(std::span<const std::byte> bytes, std::string_view name);
GroomReadResult readTressFx(const std::string& path);

// Whether the bytes are a text .tfx (TressFX 1.x/2.x): the first word is "version" or
// "numStrands".
bool isTressFxText(std::span<const std::byte> bytes);

}  // namespace csm::io
