// cyHair reader/writer: every optional-array combination, every malformed case (the error
// must name the byte offset), and a bit-exact round trip. Files are built byte by byte here
// so the tests document the layout independently of the writer.
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "sim/groom/cyhair.h"

using csm::Groom;
using csm::io::readCyHair;

namespace {

// A cyHair file as the test wants it, not necessarily consistent: each vector is written
// if non-empty, whatever `arrays` says, so the tests can make the two disagree.
struct CyHairSpec {
  char signature[4] = {'H', 'A', 'I', 'R'};
  uint32_t hairCount = 0;
  uint32_t pointCount = 0;
  uint32_t arrays = 0;
  uint32_t defaultSegments = 0;
  float defaultThickness = 1.0f;
  float defaultTransparency = 0.0f;
  float defaultColor[3] = {0.1f, 0.2f, 0.3f};
  std::vector<uint16_t> segments;
  std::vector<float> points;
  std::vector<float> thickness;
  std::vector<float> transparency;
  std::vector<float> colors;
};

template <class T>
void append(std::vector<std::byte>& out, const T* data, size_t count) {
  const auto* bytes = reinterpret_cast<const std::byte*>(data);
  out.insert(out.end(), bytes, bytes + sizeof(T) * count);
}

std::vector<std::byte> build(const CyHairSpec& spec) {
  std::vector<std::byte> out;
  append(out, spec.signature, 4);
  append(out, &spec.hairCount, 1);
  append(out, &spec.pointCount, 1);
  append(out, &spec.arrays, 1);
  append(out, &spec.defaultSegments, 1);
  append(out, &spec.defaultThickness, 1);
  append(out, &spec.defaultTransparency, 1);
  append(out, spec.defaultColor, 3);
  char info[88] = "test";
  append(out, info, 88);
  REQUIRE(out.size() == 128);
  append(out, spec.segments.data(), spec.segments.size());
  append(out, spec.points.data(), spec.points.size());
  append(out, spec.thickness.data(), spec.thickness.size());
  append(out, spec.transparency.data(), spec.transparency.size());
  append(out, spec.colors.data(), spec.colors.size());
  return out;
}

constexpr uint32_t kSegments = 1, kPoints = 2, kThickness = 4, kTransparency = 8, kColors = 16;

// Two strands of 3 and 4 points (segments array present), or 3 and 3 (default segments).
CyHairSpec validSpec(bool withSegments) {
  CyHairSpec spec;
  spec.hairCount = 2;
  spec.arrays = kPoints;
  if (withSegments) {
    spec.arrays |= kSegments;
    spec.segments = {2, 3};
    spec.pointCount = 7;
  } else {
    spec.defaultSegments = 2;
    spec.pointCount = 6;
  }
  for (uint32_t i = 0; i < spec.pointCount; ++i) {
    spec.points.insert(spec.points.end(), {0.5f * i, 10.0f + i, -0.25f * i});
  }
  return spec;
}

std::string errorOf(const CyHairSpec& spec) {
  const auto result = readCyHair(build(spec), "t.hair");
  REQUIRE_FALSE(result.groom);
  return result.error;
}

}  // namespace

TEST_CASE("cyHair: every optional array combination reads", "[io][cyhair][quick]") {
  for (uint32_t mask = 0; mask < 16; ++mask) {
    const bool withSegments = mask & 1, withThickness = mask & 2, withTransparency = mask & 4,
               withColors = mask & 8;
    CAPTURE(withSegments, withThickness, withTransparency, withColors);
    CyHairSpec spec = validSpec(withSegments);
    for (uint32_t i = 0; i < spec.pointCount; ++i) {
      if (withThickness) spec.thickness.push_back(0.01f * (i + 1));
      if (withTransparency) spec.transparency.push_back(0.5f);
      if (withColors) spec.colors.insert(spec.colors.end(), {0.1f * i, 0.5f, 2.0f});
    }
    if (withThickness) spec.arrays |= kThickness;
    if (withTransparency) spec.arrays |= kTransparency;
    if (withColors) spec.arrays |= kColors;

    const auto result = readCyHair(build(spec), "t.hair");
    INFO(result.error);
    REQUIRE(result.groom);
    const Groom& g = *result.groom;
    REQUIRE(g.strandCount() == 2);
    REQUIRE(g.pointCount() == spec.pointCount);
    CHECK(g.strandSize(0) == 3);
    CHECK(g.strandSize(1) == (withSegments ? 4u : 3u));
    for (uint32_t i = 0; i < spec.pointCount; ++i) {
      CHECK(g.points[i].x == spec.points[3 * i]);
      CHECK(g.points[i].y == spec.points[3 * i + 1]);
      CHECK(g.points[i].z == spec.points[3 * i + 2]);
    }
    if (withThickness) {
      REQUIRE(g.thickness.size() == 2);
      // Averages of the strands' points: (1+2+3)/3 * 0.01 and (4..7)/4 or (4..6)/3 * 0.01.
      CHECK(g.thickness[0] == Approx(0.02f));
      CHECK(g.thickness[1] == Approx(withSegments ? 0.055f : 0.05f));
    } else {
      CHECK(g.thickness.empty());
    }
    if (withColors) {
      REQUIRE(g.color.size() == 2);
      CHECK(g.color[0].r == Approx(0.1f));  // mean of 0, 0.1, 0.2
      CHECK(g.color[0].g == Approx(0.5f));
      CHECK(g.color[0].b == 1.0f);  // 2.0 clamped to the 0..1 the Groom promises
    } else {
      CHECK(g.color.empty());
    }
  }
}

TEST_CASE("cyHair: malformed files give errors that name the byte offset", "[io][cyhair][quick]") {
  SECTION("shorter than the header") {
    auto bytes = build(validSpec(true));
    bytes.resize(100);
    const auto result = readCyHair(bytes, "t.hair");
    REQUIRE_FALSE(result.groom);
    CHECK_THAT(result.error, Catch::Contains("t.hair: byte 0:") && Catch::Contains("128-byte") &&
                                 Catch::Contains("100 bytes"));
  }
  SECTION("empty data") {
    const auto result = readCyHair(std::span<const std::byte>(), "t.hair");
    CHECK_THAT(result.error, Catch::Contains("byte 0:"));
  }
  SECTION("wrong signature") {
    CyHairSpec spec = validSpec(true);
    std::memcpy(spec.signature, "HAIX", 4);
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 0:") && Catch::Contains("\"HAIX\""));
  }
  SECTION("no strands") {
    CyHairSpec spec = validSpec(true);
    spec.hairCount = 0;
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 4:") && Catch::Contains("hair count is 0"));
  }
  SECTION("no points array") {
    CyHairSpec spec = validSpec(true);
    spec.arrays = kSegments;
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 12:") && Catch::Contains("points bit"));
  }
  SECTION("segments array runs past the end") {
    CyHairSpec spec = validSpec(true);
    spec.hairCount = 2000;
    spec.pointCount = 4000;
    const auto bytes = build(spec);
    const std::string expected =
        "t.hair: byte 128: segments array of 4000 bytes runs past end "
        "of file (size " +
        std::to_string(bytes.size()) + ";";
    CHECK_THAT(errorOf(spec), Catch::StartsWith(expected));
  }
  SECTION("points array runs past the end") {
    CyHairSpec spec = validSpec(true);
    spec.points.resize(spec.points.size() - 3);
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 132: points array of 84 bytes runs past end"));
  }
  SECTION("colour array runs past the end") {
    CyHairSpec spec = validSpec(false);
    spec.arrays |= kThickness | kColors;
    spec.thickness.assign(6, 0.1f);
    spec.colors.assign(17, 0.5f);  // one float short
    // 128 + 72 points + 24 thickness = 224
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 224: colors array of 72 bytes runs past"));
  }
  SECTION("huge counts are refused before allocating") {
    CyHairSpec spec = validSpec(true);
    spec.hairCount = 0xFFFFFFFFu;
    spec.pointCount = 0xFFFFFFFFu;
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 8: point count 4294967295 exceeds the limit"));
    spec.pointCount = 7;
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 4: hair count 4294967295 exceeds the limit"));
  }
  SECTION("counts within limits but larger than the file") {
    CyHairSpec spec = validSpec(false);
    spec.hairCount = 3'000'000;
    spec.pointCount = 9'000'000;
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 128: points array of 108000000 bytes runs "
                                              "past end of file (size 200;"));
  }
  SECTION("trailing bytes") {
    CyHairSpec spec = validSpec(true);
    spec.pointCount = 6;  // the file holds 7 points
    CHECK_THAT(errorOf(spec),
               Catch::Contains("byte 204: 12 unexpected bytes after the last array"));
  }
  SECTION("segments sum past the point count") {
    CyHairSpec spec = validSpec(true);
    spec.segments = {2, 4};  // 3 + 5 = 8 points, the header says 7
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 130: strand 1 ends at point 8, past the "
                                              "header's point count 7"));
  }
  SECTION("segments sum short of the point count") {
    CyHairSpec spec = validSpec(true);
    spec.segments = {2, 2};  // 6 points, the header says 7
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 8: point count 7 disagrees with the segments "
                                              "array at byte 128, which sums to 6 points"));
  }
  SECTION("a strand of one point") {
    CyHairSpec spec = validSpec(true);
    spec.segments = {0, 5};
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 128: strand 0 has 0 segments (1 point)"));
  }
  SECTION("default segments disagree with the point count") {
    CyHairSpec spec = validSpec(false);
    spec.defaultSegments = 3;
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 8: point count 6 disagrees with hair count 2 "
                                              "x (default segments 3 + 1) = 8"));
    spec.defaultSegments = 0;
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 16: default segment count is 0"));
  }
  SECTION("NaN and Inf points drop their strands, named by their bytes") {
    CyHairSpec spec = validSpec(true);
    spec.points[3 * 4 + 1] = std::numeric_limits<float>::quiet_NaN();  // point 4, y
    // 128 + 4 segments bytes + 4 * 12 + 4
    auto result = readCyHair(build(spec), "t.hair");
    REQUIRE(result.groom);
    CHECK(result.groom->strandCount() == 1);
    CHECK(result.repair.droppedStrands == 1);
    REQUIRE_FALSE(result.repair.notes.empty());
    CHECK_THAT(result.repair.notes[0],
               Catch::Contains("byte 184: strand 1 dropped: coordinate y of point 1 is nan"));
    spec = validSpec(false);
    spec.points[0] = -std::numeric_limits<float>::infinity();
    result = readCyHair(build(spec), "t.hair");
    REQUIRE(result.groom);
    CHECK_THAT(result.repair.notes.at(0),
               Catch::Contains("byte 128: strand 0 dropped: coordinate x of point 0 is -inf"));
    spec.points[3 * 3 + 2] = std::numeric_limits<float>::quiet_NaN();  // strand 1 too
    CHECK_THAT(errorOf(spec), Catch::Contains("no strand can be used: all 2 were dropped"));
  }
  SECTION("a zero-length strand is dropped") {
    CyHairSpec spec = validSpec(true);
    for (int i = 3; i < 7; ++i) {  // strand 1: points 3..6 all equal
      spec.points[3 * i] = 1.0f, spec.points[3 * i + 1] = 2.0f, spec.points[3 * i + 2] = 3.0f;
    }
    const auto result = readCyHair(build(spec), "t.hair");
    REQUIRE(result.groom);
    CHECK(result.groom->strandCount() == 1);
    CHECK_THAT(result.repair.notes.at(0),
               Catch::Contains("byte 168: strand 1 dropped: all 4 points are equal"));
  }
  SECTION("negative or NaN thickness") {
    CyHairSpec spec = validSpec(true);
    spec.arrays |= kThickness;
    spec.thickness.assign(7, 0.1f);
    spec.thickness[5] = -0.5f;
    // 128 + 4 + 84 + 5 * 4
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 236: thickness of point 5 is -0.5; expected "
                                              "a finite value >= 0"));
    spec.thickness[5] = std::numeric_limits<float>::quiet_NaN();
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 236: thickness of point 5 is nan"));
  }
  SECTION("NaN colour") {
    CyHairSpec spec = validSpec(true);
    spec.arrays |= kColors;
    spec.colors.assign(21, 0.5f);
    spec.colors[7] = std::numeric_limits<float>::quiet_NaN();  // point 2, green
    CHECK_THAT(errorOf(spec), Catch::Contains("byte 244: colour component 1 of point 2 is nan"));
  }
}

TEST_CASE("cyHair: write then read gives the same groom bit for bit", "[io][cyhair][quick]") {
  Groom groom;
  uint32_t state = 12345;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / static_cast<float>(1u << 24);
  };
  for (int s = 0; s < 50; ++s) {
    std::vector<glm::vec3> strand;
    const int n = 2 + s % 37;
    for (int i = 0; i < n; ++i) strand.push_back({next() - 0.5f, next() * 1e-3f, -next() * 7e3f});
    groom.addStrand(strand);
    groom.thickness.push_back(next() * 1e-4f);
    groom.color.push_back({next(), next(), next()});
  }
  groom.points[5] = {-0.0f, std::numeric_limits<float>::denorm_min(), 1e-30f};

  std::string error;
  const auto bytes = csm::io::encodeCyHair(groom, &error);
  INFO(error);
  REQUIRE(bytes);
  // The info field says who wrote the file.
  CHECK(std::memcmp(bytes->data() + 40, "csmhair", 8) == 0);

  const auto result = readCyHair(*bytes, "roundtrip.hair");
  INFO(result.error);
  REQUIRE(result.groom);
  const Groom& back = *result.groom;
  CHECK(back.first == groom.first);
  REQUIRE(back.points.size() == groom.points.size());
  CHECK(std::memcmp(back.points.data(), groom.points.data(),
                    groom.points.size() * sizeof(glm::vec3)) == 0);
  CHECK(back.thickness == groom.thickness);
  CHECK(back.color == groom.color);

  SECTION("without optional arrays") {
    groom.thickness.clear();
    groom.color.clear();
    const auto plain = csm::io::encodeCyHair(groom, &error);
    REQUIRE(plain);
    const auto again = readCyHair(*plain);
    REQUIRE(again.groom);
    CHECK(again.groom->first == groom.first);
    CHECK(again.groom->thickness.empty());
    CHECK(again.groom->color.empty());
  }
}

TEST_CASE("cyHair: the writer refuses grooms it cannot represent", "[io][cyhair][quick]") {
  std::string error;
  Groom groom;
  groom.addStrand({{0, 0, 0}, {0, 1, 0}});
  SECTION("a NaN point") {
    groom.points[1].y = std::numeric_limits<float>::quiet_NaN();
    CHECK_FALSE(csm::io::encodeCyHair(groom, &error));
    CHECK_THAT(error, Catch::Contains("point 1 is not finite"));
  }
  SECTION("inconsistent offsets") {
    groom.first.back() = 5;
    CHECK_FALSE(csm::io::encodeCyHair(groom, &error));
    CHECK_THAT(error, Catch::Contains("fewer than 2 points") || Catch::Contains("offsets end"));
  }
  SECTION("a strand longer than the uint16 segment count") {
    groom.addStrand(std::vector<glm::vec3>(70000, glm::vec3(1.0f)));
    CHECK_FALSE(csm::io::encodeCyHair(groom, &error));
    CHECK_THAT(error, Catch::Contains("strand 1 has 70000 points"));
  }
  SECTION("no strands") {
    CHECK_FALSE(csm::io::encodeCyHair(Groom{}, &error));
    CHECK_THAT(error, Catch::Contains("no strands"));
  }
}
