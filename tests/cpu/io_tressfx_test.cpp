// TressFX .tfx reader. The files are built here by a test-only writer that follows
// TressFXFileFormat.h (160-byte TressFXTFXFileHeader, arrays at absolute byte offsets).
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "sim/groom/tressfx.h"

using csm::Groom;
using csm::io::readTressFx;

namespace {

struct TfxSpec {
  float version = 4.0f;
  uint32_t strands = 0;
  uint32_t perStrand = 0;
  std::vector<float> positions;  // float4 per vertex
  std::vector<float> strandUv;   // float2 per strand
  std::vector<float> vertexUv;   // float2 per vertex
  std::vector<float> thickness;  // float per strand
  std::vector<float> colors;     // float4 per vertex
};

struct TfxFile {
  std::vector<std::byte> bytes;
  uint32_t positionsAt = 0, strandUvAt = 0, vertexUvAt = 0, thicknessAt = 0, colorsAt = 0;

  void setU32(size_t offset, uint32_t value) { std::memcpy(bytes.data() + offset, &value, 4); }
};

// Lays the non-empty arrays out after the header, each 8-byte aligned as the format asks,
// and fills in their offsets (0 for absent arrays).
TfxFile build(const TfxSpec& spec) {
  TfxFile f;
  f.bytes.resize(160);
  auto put = [&](const std::vector<float>& data) -> uint32_t {
    if (data.empty()) return 0;
    const auto at = static_cast<uint32_t>((f.bytes.size() + 7) / 8 * 8);
    f.bytes.resize(at + 4 * data.size());
    std::memcpy(f.bytes.data() + at, data.data(), 4 * data.size());
    return at;
  };
  f.positionsAt = put(spec.positions);
  f.strandUvAt = put(spec.strandUv);
  f.vertexUvAt = put(spec.vertexUv);
  f.thicknessAt = put(spec.thickness);
  f.colorsAt = put(spec.colors);
  std::memcpy(f.bytes.data(), &spec.version, 4);
  f.setU32(4, spec.strands);
  f.setU32(8, spec.perStrand);
  f.setU32(12, f.positionsAt);
  f.setU32(16, f.strandUvAt);
  f.setU32(20, f.vertexUvAt);
  f.setU32(24, f.thicknessAt);
  f.setU32(28, f.colorsAt);
  return f;
}

// Three strands of four vertices, each going up from its root; w = 0 for the two pinned
// roots as AMD's exporter writes them.
TfxSpec validSpec() {
  TfxSpec spec;
  spec.strands = 3;
  spec.perStrand = 4;
  for (uint32_t s = 0; s < spec.strands; ++s) {
    for (uint32_t v = 0; v < spec.perStrand; ++v) {
      spec.positions.insert(spec.positions.end(),
                            {float(s), 160.0f + v, -1.0f * s, v < 2 ? 0.0f : 1.0f});
    }
  }
  return spec;
}

std::string errorOf(const std::vector<std::byte>& bytes) {
  const auto result = readTressFx(bytes, "t.tfx");
  REQUIRE_FALSE(result.groom);
  return result.error;
}

}  // namespace

TEST_CASE("TressFX: positions only", "[io][tressfx][quick]") {
  const TfxFile f = build(validSpec());
  REQUIRE(f.positionsAt == 160);
  const auto result = readTressFx(f.bytes, "t.tfx");
  INFO(result.error);
  REQUIRE(result.groom);
  const Groom& g = *result.groom;
  REQUIRE(g.strandCount() == 3);
  REQUIRE(g.pointCount() == 12);
  for (size_t s = 0; s < 3; ++s) CHECK(g.strandSize(s) == 4);
  CHECK(g.points[0] == glm::vec3(0, 160, 0));
  CHECK(g.points[7] == glm::vec3(1, 163, -1));
  CHECK(g.points[8] == glm::vec3(2, 160, -2));
  CHECK(g.thickness.empty());
  CHECK(g.color.empty());
}

TEST_CASE("TressFX: UVs, thickness and colours", "[io][tressfx][quick]") {
  TfxSpec spec = validSpec();
  spec.strandUv.assign(2 * 3, 0.5f);
  spec.vertexUv.assign(2 * 12, 0.25f);
  spec.thickness = {1.0f, 0.5f, 0.0f};
  for (uint32_t v = 0; v < 12; ++v)
    spec.colors.insert(spec.colors.end(), {0.1f * v, 0.2f, 3.0f, 1});
  const TfxFile f = build(spec);
  const auto result = readTressFx(f.bytes, "t.tfx");
  INFO(result.error);
  REQUIRE(result.groom);
  const Groom& g = *result.groom;
  CHECK(g.thickness == std::vector<float>{1.0f, 0.5f, 0.0f});
  REQUIRE(g.color.size() == 3);
  CHECK(g.color[1].r == Approx(0.55f));  // mean of 0.4..0.7
  CHECK(g.color[1].g == Approx(0.2f));
  CHECK(g.color[1].b == 1.0f);  // clamped
}

TEST_CASE("TressFX: malformed files give errors that name the byte offset",
          "[io][tressfx][quick]") {
  TfxFile f = build(validSpec());
  SECTION("shorter than the header") {
    f.bytes.resize(100);
    CHECK_THAT(errorOf(f.bytes), Catch::Contains("t.tfx: byte 0: expected a 160-byte TressFX "
                                                 "4.x header, the data has only 100 bytes"));
  }
  SECTION("no strands") {
    f.setU32(4, 0);
    CHECK_THAT(errorOf(f.bytes), Catch::Contains("byte 4: numHairStrands is 0"));
  }
  SECTION("one vertex per strand") {
    f.setU32(8, 1);
    CHECK_THAT(errorOf(f.bytes), Catch::Contains("byte 8: numVerticesPerStrand is 1"));
  }
  SECTION("no position array") {
    f.setU32(12, 0);
    CHECK_THAT(errorOf(f.bytes), Catch::Contains("byte 12: offsetVertexPosition is 0"));
  }
  SECTION("an array inside the header") {
    f.setU32(24, 100);
    CHECK_THAT(errorOf(f.bytes), Catch::Contains("byte 24: strand thickness array offset 100 "
                                                 "lies inside the 160-byte TressFX 4.x header"));
  }
  SECTION("positions run past the end") {
    f.bytes.resize(f.bytes.size() - 4);
    CHECK_THAT(errorOf(f.bytes), Catch::Contains("byte 160: vertex position array of 192 bytes "
                                                 "runs past end of file (size 348;"));
  }
  SECTION("an offset beyond the file") {
    f.setU32(28, 0xFFFFFFF0u);
    CHECK_THAT(errorOf(f.bytes), Catch::Contains("byte 4294967280: vertex colour array of 192 "
                                                 "bytes runs past end of file"));
  }
  SECTION("huge counts are refused before allocating") {
    f.setU32(4, 0xFFFFFFFFu);
    f.setU32(8, 0xFFFFFFFFu);
    CHECK_THAT(errorOf(f.bytes),
               Catch::Contains("byte 4:") && Catch::Contains("exceeds the limit"));
    f.setU32(4, 100'000);
    f.setU32(8, 64);
    CHECK_THAT(errorOf(f.bytes), Catch::Contains("byte 160: vertex position array of 102400000 "
                                                 "bytes runs past end of file (size 352;"));
  }
  SECTION("a NaN position drops its strand, named by its byte") {
    TfxSpec spec = validSpec();
    spec.positions[4 * 5 + 2] = std::numeric_limits<float>::quiet_NaN();  // vertex 5, z
    const auto result = readTressFx(build(spec).bytes, "t.tfx");
    REQUIRE(result.groom);
    CHECK(result.groom->strandCount() == 2);
    CHECK(result.repair.droppedStrands == 1);
    REQUIRE(result.repair.notes.size() == 1);
    CHECK_THAT(
        result.repair.notes[0],
        Catch::Contains("t.tfx: byte 248: strand 1 dropped: coordinate z of point 1 is nan"));
    // Every strand broken: nothing is left to simulate.
    for (size_t v = 0; v < 12; v += 4)
      spec.positions[4 * v] = std::numeric_limits<float>::infinity();
    CHECK_THAT(errorOf(build(spec).bytes),
               Catch::Contains("t.tfx: no strand can be used: all 3 were dropped"));
  }
  SECTION("a zero-length strand is dropped, named by its byte") {
    TfxSpec spec = validSpec();
    for (int v = 8; v < 12; ++v) {
      spec.positions[4 * v] = 0, spec.positions[4 * v + 1] = 0, spec.positions[4 * v + 2] = 0;
    }
    const auto result = readTressFx(build(spec).bytes, "t.tfx");
    REQUIRE(result.groom);
    CHECK(result.groom->strandCount() == 2);
    REQUIRE(result.repair.notes.size() == 1);
    CHECK_THAT(result.repair.notes[0],
               Catch::Contains("byte 288: strand 2 dropped: all 4 points are equal"));
  }
  SECTION("negative thickness") {
    TfxSpec spec = validSpec();
    spec.thickness = {1.0f, -1.0f, 1.0f};
    const TfxFile bad = build(spec);
    CHECK_THAT(errorOf(bad.bytes), Catch::Contains("byte " + std::to_string(bad.thicknessAt + 4) +
                                                   ": thickness of strand 1 is -1"));
  }
  SECTION("Inf colour") {
    TfxSpec spec = validSpec();
    spec.colors.assign(4 * 12, 0.5f);
    spec.colors[4 * 3 + 3] = std::numeric_limits<float>::infinity();  // vertex 3, alpha
    const TfxFile bad = build(spec);
    CHECK_THAT(errorOf(bad.bytes), Catch::Contains("byte " + std::to_string(bad.colorsAt + 60) +
                                                   ": colour component 3 of vertex 3 is inf"));
  }
}
