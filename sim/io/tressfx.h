// AMD TressFX 4.x binary ".tfx" files (TressFXFileFormat.h, TressFXTFXFileHeader).
// All values little-endian; the header is 160 bytes:
//
//   byte   0  float   version                 4.0 from AMD's exporters; not checked
//   byte   4  uint32  numHairStrands
//   byte   8  uint32  numVerticesPerStrand    the same for every strand (AMD: 4..64, pow2)
//   byte  12  uint32  offsetVertexPosition    float4[strands * vertices]: xyz, w = inverse
//                                             mass (0 = pinned), ignored here
//   byte  16  uint32  offsetStrandUV          float2[strands]
//   byte  20  uint32  offsetVertexUV          float2[strands * vertices]
//   byte  24  uint32  offsetStrandThickness   float[strands]
//   byte  28  uint32  offsetVertexColor       float4[strands * vertices]
//   byte  32  uint32  reserved[32]
//
// Offsets are absolute byte positions in the file; 0 means the array is absent (positions
// must be present). There is no signature: the format is recognised by its extension.
// AMD's Maya exporter writes positions (in scene units, usually centimetres) and optionally
// strand UVs only; thickness and colours come from other tools.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "sim/io/common.h"

namespace csm::io {

inline constexpr size_t kTressFxHeaderBytes = 160;

// Reads a .tfx file into a Groom. Per-strand thickness is kept as written (file units, as
// for cyHair); per-vertex colours are averaged over the strand (rgb, clamped to 0..1;
// alpha dropped). UVs are bounds-checked but not kept. Errors name the byte offset.
GroomReadResult readTressFx(std::span<const std::byte> bytes,
                            std::string_view name = "TressFX data");
GroomReadResult readTressFx(const std::string& path);

}  // namespace csm::io
