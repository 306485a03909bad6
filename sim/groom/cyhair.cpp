#include "sim/groom/cyhair.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace csm::io {
namespace {

using detail::errorAt;
using detail::floatText;
using detail::loadLE;

// Points are copied as whole arrays of three floats.
static_assert(sizeof(glm::vec3) == 12, "glm::vec3 must be three tightly packed floats");

// Bit flags of the header's `arrays` field (cyHairFile.h: CY_HAIR_FILE_*_BIT).
constexpr uint32_t kSegmentsBit = 1;
constexpr uint32_t kPointsBit = 2;
constexpr uint32_t kThicknessBit = 4;
constexpr uint32_t kTransparencyBit = 8;
constexpr uint32_t kColorsBit = 16;

// Header field offsets (see cyhair.h).
constexpr uint64_t kHairCountAt = 4;
constexpr uint64_t kPointCountAt = 8;
constexpr uint64_t kArraysAt = 12;
constexpr uint64_t kDefaultSegmentsAt = 16;
constexpr uint64_t kDefaultThicknessAt = 20;
constexpr uint64_t kDefaultTransparencyAt = 24;
constexpr uint64_t kDefaultColorAt = 28;
constexpr uint64_t kInfoAt = 40;
constexpr size_t kInfoBytes = 88;

std::string signatureText(std::span<const std::byte> bytes) {
  std::string text = "\"";
  for (int i = 0; i < 4; ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if (c >= 32 && c < 127 && c != '"' && c != '\\') {
      text += static_cast<char>(c);
    } else {
      static const char* hex = "0123456789abcdef";
      text += "\\x";
      text += hex[c >> 4];
      text += hex[c & 15];
    }
  }
  return text + "\"";
}

// Where each array starts; 0 when absent.
struct Layout {
  uint64_t segments = 0, points = 0, thickness = 0, transparency = 0, colors = 0, end = 0;
};

}  // namespace

GroomReadResult readCyHair(std::span<const std::byte> bytes, std::string_view name) {
  GroomReadResult result;
  auto fail = [&](uint64_t offset, const std::string& message) {
    result.error = errorAt(name, offset, message);
    return result;
  };
  const uint64_t size = bytes.size();
  if (size < kCyHairHeaderBytes) {
    return fail(0, "expected a " + std::to_string(kCyHairHeaderBytes) +
                       "-byte cyHair header, the data has only " + std::to_string(size) + " bytes");
  }
  if (std::memcmp(bytes.data(), "HAIR", 4) != 0) {
    return fail(0, "expected the signature \"HAIR\", found " + signatureText(bytes));
  }
  const uint64_t hairCount = loadLE<uint32_t>(bytes, kHairCountAt);
  const uint64_t pointCount = loadLE<uint32_t>(bytes, kPointCountAt);
  const uint32_t arrays = loadLE<uint32_t>(bytes, kArraysAt);
  const uint32_t defaultSegments = loadLE<uint32_t>(bytes, kDefaultSegmentsAt);

  if (hairCount == 0) return fail(kHairCountAt, "hair count is 0; expected at least 1 strand");
  if (!(arrays & kPointsBit)) {
    return fail(kArraysAt, "arrays flags " + std::to_string(arrays) +
                               " lack the points bit (2); a groom without points is empty");
  }

  // Absurd counts are refused outright (a clearer message than "past end of file"); counts
  // within the limits must still match the data size below before anything is allocated.
  if (pointCount > kMaxPoints) {
    return fail(kPointCountAt, "point count " + std::to_string(pointCount) +
                                   " exceeds the limit of " + std::to_string(kMaxPoints));
  }
  if (hairCount > kMaxStrands) {
    return fail(kHairCountAt, "hair count " + std::to_string(hairCount) + " exceeds the limit of " +
                                  std::to_string(kMaxStrands));
  }
  // Lay the arrays out and compare with the data size before allocating anything: the
  // counts are 32-bit, so every product below fits in 64 bits without overflow.
  Layout at;
  uint64_t offset = kCyHairHeaderBytes;
  struct Array {
    uint32_t bit;
    const char* label;
    uint64_t bytes;
    uint64_t* start;
  };
  const Array order[] = {
      {kSegmentsBit, "segments", 2 * hairCount, &at.segments},
      {kPointsBit, "points", 12 * pointCount, &at.points},
      {kThicknessBit, "thickness", 4 * pointCount, &at.thickness},
      {kTransparencyBit, "transparency", 4 * pointCount, &at.transparency},
      {kColorsBit, "colors", 12 * pointCount, &at.colors},
  };
  for (const Array& a : order) {
    if (!(arrays & a.bit)) continue;
    if (offset + a.bytes > size) {
      return fail(offset, std::string(a.label) + " array of " + std::to_string(a.bytes) +
                              " bytes runs past end of file (size " + std::to_string(size) +
                              "; header says " + std::to_string(hairCount) + " strands, " +
                              std::to_string(pointCount) + " points)");
    }
    *a.start = offset;
    offset += a.bytes;
  }
  at.end = offset;
  // Trailing bytes mean the counts do not describe this data; reading on would silently
  // drop strands.
  if (at.end != size) {
    return fail(at.end, std::to_string(size - at.end) +
                            " unexpected bytes after the last array; the header's counts (" +
                            std::to_string(hairCount) + " strands, " + std::to_string(pointCount) +
                            " points) account for " + std::to_string(at.end) + " bytes");
  }

  // Strand offsets, from the segments array or the default segment count.
  Groom groom;
  groom.first.clear();
  groom.first.reserve(hairCount + 1);
  groom.first.push_back(0);
  if (at.segments) {
    uint64_t total = 0;
    for (uint64_t s = 0; s < hairCount; ++s) {
      const uint64_t entryAt = at.segments + 2 * s;
      const uint16_t segments = loadLE<uint16_t>(bytes, entryAt);
      if (segments == 0) {
        return fail(entryAt, "strand " + std::to_string(s) +
                                 " has 0 segments (1 point); expected at least 1 segment");
      }
      total += uint64_t{segments} + 1;
      if (total > pointCount) {
        return fail(entryAt, "strand " + std::to_string(s) + " ends at point " +
                                 std::to_string(total) + ", past the header's point count " +
                                 std::to_string(pointCount));
      }
      groom.first.push_back(static_cast<uint32_t>(total));
    }
    if (total != pointCount) {
      return fail(kPointCountAt, "point count " + std::to_string(pointCount) +
                                     " disagrees with the segments array at byte " +
                                     std::to_string(at.segments) + ", which sums to " +
                                     std::to_string(total) + " points");
    }
  } else {
    if (defaultSegments == 0) {
      return fail(kDefaultSegmentsAt,
                  "default segment count is 0 and there is no segments array; expected at "
                  "least 1 segment per strand");
    }
    const uint64_t perStrand = uint64_t{defaultSegments} + 1;
    if (hairCount * perStrand != pointCount) {
      return fail(kPointCountAt, "point count " + std::to_string(pointCount) +
                                     " disagrees with hair count " + std::to_string(hairCount) +
                                     " x (default segments " + std::to_string(defaultSegments) +
                                     " + 1) = " + std::to_string(hairCount * perStrand));
    }
    for (uint64_t s = 1; s <= hairCount; ++s) {
      groom.first.push_back(static_cast<uint32_t>(s * perStrand));
    }
  }

  groom.points.resize(pointCount);
  std::memcpy(groom.points.data(), bytes.data() + at.points, 12 * pointCount);

  if (at.thickness) {
    for (uint64_t i = 0; i < pointCount; ++i) {
      const float t = loadLE<float>(bytes, at.thickness + 4 * i);
      if (!(t >= 0.0f) || !std::isfinite(t)) {
        return fail(at.thickness + 4 * i, "thickness of point " + std::to_string(i) + " is " +
                                              floatText(t) + "; expected a finite value >= 0");
      }
    }
  }
  if (at.transparency) {
    for (uint64_t i = 0; i < pointCount; ++i) {
      const float t = loadLE<float>(bytes, at.transparency + 4 * i);
      if (!std::isfinite(t)) {
        return fail(at.transparency + 4 * i, "transparency of point " + std::to_string(i) + " is " +
                                                 floatText(t) + "; expected a finite number");
      }
    }
  }
  if (at.colors) {
    for (uint64_t k = 0; k < 3 * pointCount; ++k) {
      const float c = loadLE<float>(bytes, at.colors + 4 * k);
      if (!std::isfinite(c)) {
        return fail(at.colors + 4 * k, "colour component " + std::to_string(k % 3) + " of point " +
                                           std::to_string(k / 3) + " is " + floatText(c) +
                                           "; expected a finite number");
      }
    }
  }

  // Per-point values become one per strand by averaging; double sums keep the average of
  // identical values exact, so a file written by writeCyHair reads back bit for bit.
  if (at.thickness) {
    groom.thickness.resize(hairCount);
    for (size_t s = 0; s < hairCount; ++s) {
      double sum = 0;
      for (uint32_t i = groom.first[s]; i < groom.first[s + 1]; ++i) {
        sum += loadLE<float>(bytes, at.thickness + 4 * uint64_t{i});
      }
      groom.thickness[s] = static_cast<float>(sum / groom.strandSize(s));
    }
  }
  if (at.colors) {
    groom.color.resize(hairCount);
    for (size_t s = 0; s < hairCount; ++s) {
      double sum[3] = {0, 0, 0};
      for (uint32_t i = groom.first[s]; i < groom.first[s + 1]; ++i) {
        for (int c = 0; c < 3; ++c) sum[c] += loadLE<float>(bytes, at.colors + 12 * i + 4 * c);
      }
      for (int c = 0; c < 3; ++c) {
        groom.color[s][c] =
            std::clamp(static_cast<float>(sum[c] / groom.strandSize(s)), 0.0f, 1.0f);
      }
    }
  }
  detail::finishGroom(result, std::move(groom), name, detail::byteOfPoint(at.points, 12));
  return result;
}

GroomReadResult readCyHair(const std::string& path) {
  return detail::readGroomFile(path, [](std::span<const std::byte> bytes, std::string_view name) {
    return readCyHair(bytes, name);
  });
}

std::optional<std::vector<std::byte>> encodeCyHair(const Groom& groom, std::string* error) {
  auto fail = [&](const std::string& message) -> std::optional<std::vector<std::byte>> {
    if (error) *error = "cyHair writer: " + message;
    return std::nullopt;
  };
  if (std::string problem = checkGroomStructure(groom); !problem.empty()) return fail(problem);
  const uint64_t hairCount = groom.strandCount();
  const uint64_t pointCount = groom.pointCount();
  if (hairCount == 0) return fail("the groom has no strands");
  if (pointCount > std::numeric_limits<uint32_t>::max()) return fail("too many points");
  for (size_t s = 0; s < hairCount; ++s) {
    if (groom.strandSize(s) - 1 > std::numeric_limits<uint16_t>::max()) {
      return fail("strand " + std::to_string(s) + " has " + std::to_string(groom.strandSize(s)) +
                  " points; the segments array holds at most 65536 per strand");
    }
  }
  for (size_t i = 0; i < pointCount; ++i) {
    const glm::vec3& p = groom.points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      return fail("point " + std::to_string(i) + " is not finite");
    }
  }
  const bool hasThickness = !groom.thickness.empty();
  const bool hasColor = !groom.color.empty();
  for (size_t s = 0; hasThickness && s < hairCount; ++s) {
    if (!(groom.thickness[s] >= 0.0f) || !std::isfinite(groom.thickness[s])) {
      return fail("thickness of strand " + std::to_string(s) + " is " +
                  floatText(groom.thickness[s]));
    }
  }
  for (size_t s = 0; hasColor && s < hairCount; ++s) {
    const glm::vec3& c = groom.color[s];
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
      return fail("colour of strand " + std::to_string(s) + " is not finite");
    }
  }

  uint32_t arrays = kSegmentsBit | kPointsBit;
  uint64_t size = kCyHairHeaderBytes + 2 * hairCount + 12 * pointCount;
  if (hasThickness) arrays |= kThicknessBit, size += 4 * pointCount;
  if (hasColor) arrays |= kColorsBit, size += 12 * pointCount;
  std::vector<std::byte> out(size);
  auto put = [&](uint64_t offset, const void* data, size_t n) {
    std::memcpy(out.data() + offset, data, n);
  };
  auto putU32 = [&](uint64_t offset, uint32_t v) { put(offset, &v, 4); };
  auto putF32 = [&](uint64_t offset, float v) { put(offset, &v, 4); };

  put(0, "HAIR", 4);
  putU32(kHairCountAt, static_cast<uint32_t>(hairCount));
  putU32(kPointCountAt, static_cast<uint32_t>(pointCount));
  putU32(kArraysAt, arrays);
  // Defaults for readers that ignore the arrays: first strand's segments, 0.1 mm thickness
  // (a typical human hair), opaque, mid grey.
  putU32(kDefaultSegmentsAt, groom.strandSize(0) - 1);
  putF32(kDefaultThicknessAt, hasThickness ? groom.thickness[0] : 1e-4f);
  putF32(kDefaultTransparencyAt, 0.0f);
  const float grey[3] = {0.5f, 0.5f, 0.5f};
  put(kDefaultColorAt, hasColor ? &groom.color[0][0] : grey, 12);
  const char info[] = "csmhair";
  static_assert(sizeof(info) <= kInfoBytes);
  put(kInfoAt, info, sizeof(info));  // the rest of info[] stays zero

  uint64_t offset = kCyHairHeaderBytes;
  for (size_t s = 0; s < hairCount; ++s, offset += 2) {
    const auto segments = static_cast<uint16_t>(groom.strandSize(s) - 1);
    put(offset, &segments, 2);
  }
  put(offset, groom.points.data(), 12 * pointCount);
  offset += 12 * pointCount;
  if (hasThickness) {
    for (size_t s = 0; s < hairCount; ++s) {
      for (uint32_t i = groom.first[s]; i < groom.first[s + 1]; ++i, offset += 4) {
        putF32(offset, groom.thickness[s]);
      }
    }
  }
  if (hasColor) {
    for (size_t s = 0; s < hairCount; ++s) {
      for (uint32_t i = groom.first[s]; i < groom.first[s + 1]; ++i, offset += 12) {
        put(offset, &groom.color[s][0], 12);
      }
    }
  }
  return out;
}

bool writeCyHair(const std::string& path, const Groom& groom, std::string* error) {
  std::string problem;
  auto bytes = encodeCyHair(groom, &problem);
  if (!bytes) {
    if (error) *error = path + ": " + problem;
    return false;
  }
  return detail::writeFileAtomically(path, *bytes, error);
}

}  // namespace csm::io
