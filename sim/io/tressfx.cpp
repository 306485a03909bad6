#include "sim/io/tressfx.h"

#include <algorithm>
#include <cmath>

namespace csm::io {
namespace {

using detail::errorAt;
using detail::floatText;
using detail::loadLE;

// Header field offsets (see tressfx.h).
constexpr uint64_t kStrandsAt = 4;
constexpr uint64_t kVerticesAt = 8;
constexpr uint64_t kPositionOffsetAt = 12;
constexpr uint64_t kStrandUvOffsetAt = 16;
constexpr uint64_t kVertexUvOffsetAt = 20;
constexpr uint64_t kThicknessOffsetAt = 24;
constexpr uint64_t kColorOffsetAt = 28;

}  // namespace

GroomReadResult readTressFx(std::span<const std::byte> bytes, std::string_view name) {
  GroomReadResult result;
  auto fail = [&](uint64_t offset, const std::string& message) {
    result.error = errorAt(name, offset, message);
    return result;
  };
  const uint64_t size = bytes.size();
  if (size < kTressFxHeaderBytes) {
    return fail(0, "expected a " + std::to_string(kTressFxHeaderBytes) +
                       "-byte TressFX header, the data has only " + std::to_string(size) +
                       " bytes");
  }
  const uint64_t strands = loadLE<uint32_t>(bytes, kStrandsAt);
  const uint64_t perStrand = loadLE<uint32_t>(bytes, kVerticesAt);
  if (strands == 0) return fail(kStrandsAt, "numHairStrands is 0; expected at least 1 strand");
  if (perStrand < 2) {
    return fail(kVerticesAt,
                "numVerticesPerStrand is " + std::to_string(perStrand) + "; expected at least 2");
  }
  // Both counts are 32-bit, so their product fits in 64 bits; after the cap below, so does
  // every array size.
  const uint64_t vertices = strands * perStrand;

  if (vertices > kMaxPoints) {
    return fail(kStrandsAt, std::to_string(strands) + " strands x " + std::to_string(perStrand) +
                                " vertices exceeds the limit of " + std::to_string(kMaxPoints) +
                                " points");
  }
  // Every array must lie after the header and inside the data; check before allocating.
  struct Array {
    uint64_t fieldAt;
    const char* label;
    uint64_t bytes;
  };
  const Array arrays[] = {
      {kPositionOffsetAt, "vertex position", 16 * vertices},
      {kStrandUvOffsetAt, "strand UV", 8 * strands},
      {kVertexUvOffsetAt, "vertex UV", 8 * vertices},
      {kThicknessOffsetAt, "strand thickness", 4 * strands},
      {kColorOffsetAt, "vertex colour", 16 * vertices},
  };
  for (const Array& a : arrays) {
    const uint64_t start = loadLE<uint32_t>(bytes, a.fieldAt);
    if (start == 0) {
      if (a.fieldAt == kPositionOffsetAt) {
        return fail(a.fieldAt, "offsetVertexPosition is 0; expected the position array");
      }
      continue;
    }
    if (start < kTressFxHeaderBytes) {
      return fail(a.fieldAt, std::string(a.label) + " array offset " + std::to_string(start) +
                                 " lies inside the 160-byte header");
    }
    if (start + a.bytes > size) {
      return fail(start, std::string(a.label) + " array of " + std::to_string(a.bytes) +
                             " bytes runs past end of file (size " + std::to_string(size) +
                             "; header says " + std::to_string(strands) + " strands x " +
                             std::to_string(perStrand) + " vertices)");
    }
  }

  const uint64_t positionsAt = loadLE<uint32_t>(bytes, kPositionOffsetAt);
  const uint64_t thicknessAt = loadLE<uint32_t>(bytes, kThicknessOffsetAt);
  const uint64_t colorsAt = loadLE<uint32_t>(bytes, kColorOffsetAt);

  Groom groom;
  groom.first.resize(strands + 1);
  for (uint64_t s = 0; s <= strands; ++s) groom.first[s] = static_cast<uint32_t>(s * perStrand);
  groom.points.resize(vertices);
  for (uint64_t i = 0; i < vertices; ++i) {
    const uint64_t at = positionsAt + 16 * i;
    groom.points[i] = {loadLE<float>(bytes, at), loadLE<float>(bytes, at + 4),
                       loadLE<float>(bytes, at + 8)};
  }
  if (std::string error = detail::checkPoints(groom, name, positionsAt, 16); !error.empty()) {
    result.error = std::move(error);
    return result;
  }

  if (thicknessAt) {
    groom.thickness.resize(strands);
    for (uint64_t s = 0; s < strands; ++s) {
      const float t = loadLE<float>(bytes, thicknessAt + 4 * s);
      if (!(t >= 0.0f) || !std::isfinite(t)) {
        return fail(thicknessAt + 4 * s, "thickness of strand " + std::to_string(s) + " is " +
                                             floatText(t) + "; expected a finite value >= 0");
      }
      groom.thickness[s] = t;
    }
  }
  if (colorsAt) {
    groom.color.resize(strands);
    for (uint64_t s = 0; s < strands; ++s) {
      double sum[3] = {0, 0, 0};
      for (uint64_t v = s * perStrand; v < (s + 1) * perStrand; ++v) {
        for (int c = 0; c < 4; ++c) {
          const uint64_t at = colorsAt + 16 * v + 4 * c;
          const float value = loadLE<float>(bytes, at);
          if (!std::isfinite(value)) {
            return fail(at, "colour component " + std::to_string(c) + " of vertex " +
                                std::to_string(v) + " is " + floatText(value) +
                                "; expected a finite number");
          }
          if (c < 3) sum[c] += value;
        }
      }
      for (int c = 0; c < 3; ++c) {
        groom.color[s][c] =
            std::clamp(static_cast<float>(sum[c] / static_cast<double>(perStrand)), 0.0f, 1.0f);
      }
    }
  }
  result.groom = std::move(groom);
  return result;
}

GroomReadResult readTressFx(const std::string& path) {
  GroomReadResult result;
  auto bytes = detail::readFileBytes(path, kMaxFileBytes, &result.error);
  if (!bytes) return result;
  return readTressFx(*bytes, path);
}

}  // namespace csm::io
