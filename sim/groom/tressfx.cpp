#include "sim/groom/tressfx.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/mat3x3.hpp>

#include "sim/base/obj_text.h"

namespace csm::io {
namespace {

using detail::errorAt;
using detail::floatText;
using detail::loadLE;

// One array of a binary layout: the header field holding its offset, and its size.
struct ArrayField {
  uint64_t fieldAt;
  const char* label;
  uint64_t elementBytes;
  bool perVertex;  // else per strand
};

// What differs between the binary versions (tressfx.h).
struct BinaryLayout {
  const char* strandsName;
  const char* positionsName;
  uint64_t headerBytes;
  uint64_t positionStride;         // float3 in 3.x, float4 in 4.x
  std::vector<ArrayField> arrays;  // positions first
  int thickness, colors;           // indices into arrays, -1: none
};

const BinaryLayout& layout3() {
  static const BinaryLayout l{"numGuideHairStrands",
                              "verticesOffset",
                              kTressFx3HeaderBytes,
                              12,
                              {{144, "vertex position", 12, true},
                               {148, "strand thickness", 4, false},
                               {152, "strand texture coordinate", 8, false},
                               {156, "vertex colour", 16, true},
                               {160, "guide hair flag", 4, false},
                               {164, "vertex texture coordinate", 8, true}},
                              1,
                              3};
  return l;
}

const BinaryLayout& layout4() {
  static const BinaryLayout l{"numHairStrands",
                              "offsetVertexPosition",
                              kTressFxHeaderBytes,
                              16,
                              {{12, "vertex position", 16, true},
                               {16, "strand UV", 8, false},
                               {20, "vertex UV", 8, true},
                               {24, "strand thickness", 4, false},
                               {28, "vertex colour", 16, true}},
                              3,
                              4};
  return l;
}

constexpr uint64_t kStrandsAt = 4;
constexpr uint64_t kVerticesAt = 8;
constexpr uint64_t kBothEndsAt3 = 16;

GroomReadResult readBinary(std::span<const std::byte> bytes, std::string_view name,
                           const BinaryLayout& layout) {
  GroomReadResult result;
  auto fail = [&](uint64_t offset, const std::string& message) {
    result.error = errorAt(name, offset, message);
    return result;
  };
  const uint64_t size = bytes.size();
  const std::string format = &layout == &layout3() ? "TressFX 3.x" : "TressFX 4.x";
  if (size < layout.headerBytes) {
    return fail(0, "expected a " + std::to_string(layout.headerBytes) + "-byte " + format +
                       " header, the data has only " + std::to_string(size) + " bytes");
  }
  const uint64_t strands = loadLE<uint32_t>(bytes, kStrandsAt);
  const uint64_t perStrand = loadLE<uint32_t>(bytes, kVerticesAt);
  if (strands == 0)
    return fail(kStrandsAt, std::string(layout.strandsName) + " is 0; expected at least 1 strand");
  if (perStrand < 2) {
    return fail(kVerticesAt,
                "numVerticesPerStrand is " + std::to_string(perStrand) + "; expected at least 2");
  }
  // 3.x: one flag for the file (AMD's exporters write a bool: the byte, then padding).
  const bool bothEnds = &layout == &layout3() && loadLE<uint8_t>(bytes, kBothEndsAt3) != 0;
  // Both counts are 32-bit, so their product fits in 64 bits; after the cap below, so does
  // every array size.
  const uint64_t vertices = strands * perStrand;
  if (vertices > kMaxPoints) {
    return fail(kStrandsAt, std::to_string(strands) + " strands x " + std::to_string(perStrand) +
                                " vertices exceeds the limit of " + std::to_string(kMaxPoints) +
                                " points");
  }
  // Every array must lie after the header and inside the data; check before allocating.
  std::vector<uint64_t> starts;
  for (const ArrayField& a : layout.arrays) {
    const uint64_t start = loadLE<uint32_t>(bytes, a.fieldAt);
    const uint64_t arrayBytes = a.elementBytes * (a.perVertex ? vertices : strands);
    starts.push_back(start);
    if (start == 0) {
      if (&a == &layout.arrays.front())
        return fail(a.fieldAt, std::string(layout.positionsName) +
                                   " is 0; expected the position array (" + format + " layout)");
      continue;
    }
    if (start < layout.headerBytes) {
      return fail(a.fieldAt, std::string(a.label) + " array offset " + std::to_string(start) +
                                 " lies inside the " + std::to_string(layout.headerBytes) +
                                 "-byte " + format + " header");
    }
    if (start + arrayBytes > size) {
      return fail(start, std::string(a.label) + " array of " + std::to_string(arrayBytes) +
                             " bytes runs past end of file (size " + std::to_string(size) +
                             "; header says " + std::to_string(strands) + " strands x " +
                             std::to_string(perStrand) + " vertices)");
    }
  }
  const uint64_t positionsAt = starts[0];
  const uint64_t thicknessAt = starts[size_t(layout.thickness)];
  const uint64_t colorsAt = starts[size_t(layout.colors)];

  Groom groom;
  groom.first.resize(strands + 1);
  for (uint64_t s = 0; s <= strands; ++s) groom.first[s] = static_cast<uint32_t>(s * perStrand);
  groom.points.resize(vertices);
  for (uint64_t i = 0; i < vertices; ++i) {
    const uint64_t at = positionsAt + layout.positionStride * i;
    groom.points[i] = {loadLE<float>(bytes, at), loadLE<float>(bytes, at + 4),
                       loadLE<float>(bytes, at + 8)};
  }
  if (bothEnds) {
    groom.tipHeld.assign(strands, 1);
  } else if (layout.positionStride == 16) {
    // 4.x: w is the vertex's inverse mass (0: the head holds it), written by the exporters' "both
    // ends immovable" as 0 on each strand's last vertices too. A file whose every w is 0 holds no
    // masses (some tools leave w unset): its tips are free.
    std::vector<uint8_t> held(strands, 0);
    bool masses = false;
    for (uint64_t i = 0; i < vertices; ++i)
      masses = masses || loadLE<float>(bytes, positionsAt + 16 * i + 12) != 0.0f;
    for (uint64_t s = 0; masses && s < strands; ++s)
      held[s] = loadLE<float>(bytes, positionsAt + 16 * ((s + 1) * perStrand - 1) + 12) == 0.0f;
    if (masses && std::find(held.begin(), held.end(), 1) != held.end()) groom.tipHeld = held;
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
  detail::finishGroom(result, std::move(groom), name,
                      detail::byteOfPoint(positionsAt, layout.positionStride));
  return result;
}

// The AMD loader's transform of a 2.x file: scale, then XMMatrixRotationRollPitchYaw(x, y, z)
// (roll about z, then pitch about x, then yaw about y), then the translation.
glm::mat3 rollPitchYaw(const glm::vec3& r) {
  const float cx = std::cos(r.x), sx = std::sin(r.x);
  const float cy = std::cos(r.y), sy = std::sin(r.y);
  const float cz = std::cos(r.z), sz = std::sin(r.z);
  const glm::mat3 rx({1, 0, 0}, {0, cx, sx}, {0, -sx, cx});  // glm: columns
  const glm::mat3 ry({cy, 0, -sy}, {0, 1, 0}, {sy, 0, cy});
  const glm::mat3 rz({cz, sz, 0}, {-sz, cz, 0}, {0, 0, 1});
  return ry * rx * rz;
}

// A number of the text form; Windows' printf writes infinities as "1.#INF" and NaN as
// "1.#IND" or "1.#QNAN", which the exporters of 1.x/2.x files did: they read as not finite,
// so the repair drops their strand (AMD's loader skipped such a vertex).
bool textNumber(std::string_view token, double& value) {
  if (token.find("#INF") != std::string_view::npos) {
    value = token.front() == '-' ? -INFINITY : INFINITY;
    return true;
  }
  if (token.find("#IND") != std::string_view::npos ||
      token.find("#QNAN") != std::string_view::npos ||
      token.find("#SNAN") != std::string_view::npos) {
    value = NAN;
    return true;
  }
  return detail::parseNumber(token, value);
}

GroomReadResult readText(std::span<const std::byte> bytes, std::string_view name) {
  GroomReadResult result;
  const std::string_view text = detail::withoutBom(
      std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  // Line by line, a few tokens a line: nothing held grows with a line's length. Comments are not
  // part of the format (and "1.#INF" holds a '#').
  detail::LineCursor lines(text);
  auto fail = [&](size_t line, const std::string& message) {
    result.error = std::string(name) + ":" + std::to_string(line) + ": " + message;
    return result;
  };
  auto numbers = [&](const std::vector<std::string_view>& t, size_t from, size_t count,
                     const char* what, double* out) -> std::string {
    if (t.size() < from + count)
      return std::string(what) + " needs " + std::to_string(count) + " numbers, the line has " +
             std::to_string(t.size() - std::min(t.size(), from));
    for (size_t i = 0; i < count; ++i)
      if (!textNumber(t[from + i], out[i]))
        return std::string(what) + ": \"" + std::string(t[from + i]) + "\" is not a number";
    return {};
  };
  size_t line = 0;
  std::string_view raw;

  float scale = 1.0f;
  glm::vec3 rotation(0.0f), translation(0.0f);
  bool bothEnds = false;
  uint64_t strands = 0;
  bool haveStrands = false;
  while (!haveStrands && lines.next(line, raw)) {
    const auto t = detail::objTokens(raw, 4);
    if (t.empty()) continue;
    double v[3];
    if (t[0] == "version" || t[0] == "scale") {
      if (auto e = numbers(t, 1, 1, t[0] == "version" ? "version" : "scale", v); !e.empty())
        return fail(line, e);
      if (t[0] == "scale") scale = float(v[0]);
    } else if (t[0] == "rotation" || t[0] == "translation") {
      if (auto e = numbers(t, 1, 3, t[0] == "rotation" ? "rotation" : "translation", v); !e.empty())
        return fail(line, e);
      (t[0] == "rotation" ? rotation : translation) = glm::vec3(v[0], v[1], v[2]);
    } else if (t[0] == "bothEndsImmovable") {
      if (auto e = numbers(t, 1, 1, "bothEndsImmovable", v); !e.empty()) return fail(line, e);
      bothEnds = v[0] != 0.0;
    } else if (t[0] == "numStrands") {
      long n = 0;
      if (t.size() < 2 || !detail::parseIndex(t[1], n) || n < 1)
        return fail(line, "numStrands needs a whole number of strands, at least 1");
      if (uint64_t(n) > kMaxStrands)
        return fail(line, "numStrands " + std::to_string(n) + " exceeds the limit of " +
                              std::to_string(kMaxStrands) + " strands");
      strands = uint64_t(n);
      haveStrands = true;
    }
    // Other keywords (maxNumVerticesInStrand, numFollowHairsPerGuideHair,
    // maxRadiusAroundGuideHair) say how AMD's runtime makes follow hairs: nothing to read.
  }
  if (!haveStrands)
    return fail(lines.lastNonBlank(),
                "no \"numStrands\" line; a TressFX text file names its strand count before the "
                "strands");

  const glm::mat3 turn = rollPitchYaw(rotation);
  Groom groom;
  GroomRepair shortOnes;  // strands of fewer than two vertices: dropped here
  std::vector<size_t> pointLine, fileStrand;
  std::vector<glm::vec3> strand;
  for (uint64_t s = 0; s < strands; ++s) {
    // The strand line: "strand i numVerts n [texcoord u v]"; blank lines and "is sorted" before.
    std::vector<std::string_view> t;
    bool found = false;
    while (!found && lines.next(line, raw)) {
      t = detail::objTokens(raw, 4);
      found = !t.empty() && t[0] != "is";
    }
    if (!found)
      return fail(lines.lastNonBlank(), "the file ends after " + std::to_string(s) + " of the " +
                                            std::to_string(strands) + " strands numStrands names");
    const size_t strandLine = line;
    long n = 0;
    if (t[0] != "strand" || t.size() < 4 || t[2] != "numVerts" || !detail::parseIndex(t[3], n) ||
        n < 0)
      return fail(line, "expected \"strand " + std::to_string(s) +
                            " numVerts N\", the start of strand " + std::to_string(s));
    if (groom.points.size() + uint64_t(n) > kMaxPoints)
      return fail(
          line, "the strands so far exceed the limit of " + std::to_string(kMaxPoints) + " points");
    strand.clear();
    for (long i = 0; i < n; ++i) {
      if (!lines.next(line, raw))
        return fail(lines.lastNonBlank(), "the file ends inside strand " + std::to_string(s) +
                                              " (" + std::to_string(i) + " of its " +
                                              std::to_string(n) + " vertices)");
      const auto p = detail::objTokens(raw, 3);
      double v[3];
      if (auto e = numbers(p, 0, 3, "a vertex", v); !e.empty()) return fail(line, e);
      const glm::vec3 point{float(v[0]), float(v[1]), float(v[2])};
      // A point that is not finite stays as written: the repair names its value.
      const bool finite =
          std::isfinite(point.x) && std::isfinite(point.y) && std::isfinite(point.z);
      strand.push_back(finite ? turn * (scale * point) + translation : point);
      pointLine.push_back(line);
    }
    if (strand.size() < 2) {
      ++shortOnes.droppedStrands;
      if (shortOnes.notes.size() < GroomRepair::kMaxNotes)
        shortOnes.notes.push_back(std::string(name) + ": line " + std::to_string(strandLine) +
                                  ": strand " + std::to_string(s) + " dropped: it has " +
                                  std::to_string(strand.size()) + " vertices");
      pointLine.resize(pointLine.size() - strand.size());
      continue;
    }
    groom.addStrand(strand);
    fileStrand.push_back(size_t(s));
  }
  if (groom.strandCount() == 0)
    return fail(lines.lastNonBlank(), "no strand has 2 vertices or more");
  result.repair = shortOnes;
  if (bothEnds) groom.tipHeld.assign(groom.strandCount(), 1);
  detail::finishGroom(
      result, std::move(groom), name,
      [pointLine](size_t point, int) {
        return "line " + std::to_string(point < pointLine.size() ? pointLine[point] : 0);
      },
      std::move(fileStrand));
  return result;
}

}  // namespace

bool isTressFxText(std::span<const std::byte> bytes) {
  const std::string_view text = detail::withoutBom(std::string_view(
      reinterpret_cast<const char*>(bytes.data()), std::min<size_t>(bytes.size(), 256)));
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  size_t i = 0;
  while (i < text.size() && space(text[i])) ++i;
  const std::string_view rest = text.substr(i);
  auto word = [&](std::string_view w) {
    return rest.substr(0, w.size()) == w && (rest.size() == w.size() || space(rest[w.size()]));
  };
  return word("version") || word("numStrands");
}

GroomReadResult readTressFxLayout(std::span<const std::byte> bytes, std::string_view name);

GroomReadResult readTressFx(std::span<const std::byte> bytes, std::string_view name) {
  GroomReadResult r = readTressFxLayout(bytes, name);
  r.facesMinusZ = true;  // every version: DirectX's left-handed axes, the face toward -z
  return r;
}

GroomReadResult readTressFxLayout(std::span<const std::byte> bytes, std::string_view name) {
  if (isTressFxText(bytes)) return readText(bytes, name);
  if (bytes.size() < 4) {
    GroomReadResult result;
    result.error = errorAt(name, 0,
                           "expected a TressFX header (a version, then counts and offsets), the "
                           "data has only " +
                               std::to_string(bytes.size()) + " bytes");
    return result;
  }
  const float version = loadLE<float>(bytes, 0);
  const bool three = version >= 3.0f && version < 4.0f;
  return readBinary(bytes, name, three ? layout3() : layout4());
}

GroomReadResult readTressFx(const std::string& path) {
  return detail::readGroomFile(path, [](std::span<const std::byte> bytes, std::string_view name) {
    return readTressFx(bytes, name);
  });
}

}  // namespace csm::io
