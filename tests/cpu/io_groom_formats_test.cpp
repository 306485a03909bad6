// Grooms as the field's tools write them: TressFX 1.x/2.x text, 3.x and 4.x binary, OBJ
// curves in Blender's edge-per-line form and in polyline form; the files are written here from
// the same strands, by test-only writers that follow each format's layout (sim/groom/tressfx.h,
// sim/groom/obj_curves.h), and must read back to the same points.
#include <cmath>
#include <cstring>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "sim/groom/cyhair.h"
#include "sim/groom/groom_file.h"
#include "sim/groom/obj_curves.h"
#include "sim/groom/research_formats.h"
#include "sim/groom/repair.h"
#include "sim/groom/tressfx.h"

using csm::Groom;

namespace {

// Five strands of eight points, each its own shape; exact in float and in "%.9g" text.
Groom sampleStrands() {
  Groom g;
  for (int s = 0; s < 5; ++s) {
    std::vector<glm::vec3> pts;
    for (int i = 0; i < 8; ++i)
      pts.emplace_back(0.25f * s + 0.125f * i, 10.0f - 0.5f * i * i / 8.0f, -0.375f * s + i);
    g.addStrand(pts);
    g.thickness.push_back(0.01f * float(s + 1));
  }
  return g;
}

std::span<const std::byte> bytesOf(const std::string& text) {
  return std::as_bytes(std::span(text.data(), text.size()));
}

struct Binary {
  std::vector<std::byte> bytes;
  void put(size_t at, const void* data, size_t size) {
    if (bytes.size() < at + size) bytes.resize(at + size);
    std::memcpy(bytes.data() + at, data, size);
  }
  void u32(size_t at, uint32_t v) { put(at, &v, 4); }
  void f32(size_t at, float v) { put(at, &v, 4); }
  // Appends 8-byte aligned, returns the offset.
  uint32_t append(const std::vector<float>& data) {
    const auto at = uint32_t((bytes.size() + 7) / 8 * 8);
    put(at, data.data(), 4 * data.size());
    return at;
  }
};

// TressFX 3.x (TressFXFileObject): 296 bytes of header, float3 positions.
Binary tressFx3(const Groom& g, uint32_t perStrand) {
  Binary f;
  f.bytes.resize(csm::io::kTressFx3HeaderBytes);
  f.f32(0, 3.0f);
  f.u32(4, uint32_t(g.strandCount()));
  f.u32(8, perStrand);
  f.u32(12, 4);  // follow hairs: AMD's runtime makes them
  std::vector<float> pos, colour, guide;
  for (const glm::vec3& p : g.points) pos.insert(pos.end(), {p.x, p.y, p.z});
  for (size_t v = 0; v < g.pointCount(); ++v) colour.insert(colour.end(), {0.5f, 0.25f, 0, 1});
  f.u32(144, f.append(pos));
  f.u32(148, f.append(g.thickness));
  f.u32(156, f.append(colour));
  f.u32(160, f.append(std::vector<float>(g.strandCount(), 0.0f)));  // uint 0: guide
  return f;
}

// TressFX 4.x (TressFXTFXFileHeader): 160 bytes, float4 positions.
Binary tressFx4(const Groom& g, uint32_t perStrand) {
  Binary f;
  f.bytes.resize(csm::io::kTressFxHeaderBytes);
  f.f32(0, 4.0f);
  f.u32(4, uint32_t(g.strandCount()));
  f.u32(8, perStrand);
  std::vector<float> pos;
  for (size_t i = 0; i < g.pointCount(); ++i) {
    const glm::vec3& p = g.points[i];
    pos.insert(pos.end(), {p.x, p.y, p.z, i % perStrand < 2 ? 0.0f : 1.0f});
  }
  f.u32(12, f.append(pos));
  f.u32(24, f.append(g.thickness));
  return f;
}

std::string number(float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", double(v));
  return buf;
}

// TressFX 2.x text, as AMD's Maya exporter wrote it.
std::string tressFxText(const Groom& g, const std::string& header) {
  std::string t = header + "numStrands " + std::to_string(g.strandCount()) + "\nis sorted 1\n";
  for (size_t s = 0; s < g.strandCount(); ++s) {
    t += "strand " + std::to_string(s) + " numVerts " + std::to_string(g.strandSize(s)) +
         " texcoord 0.000000 0.500000\n";
    for (uint32_t i = g.first[s]; i < g.first[s + 1]; ++i)
      t += number(g.points[i].x) + " " + number(g.points[i].y) + " " + number(g.points[i].z) + "\n";
  }
  return t;
}

std::string objVertices(const Groom& g) {
  std::string t = "# Blender v3.4.1 OBJ File: ''\no ParticleSystem\n";
  for (const glm::vec3& p : g.points)
    t += "v " + number(p.x) + " " + number(p.y) + " " + number(p.z) + "\n";
  return t;
}

// Blender's form: one `l i j` an edge.
std::string objEdges(const Groom& g) {
  std::string t = objVertices(g);
  for (size_t s = 0; s < g.strandCount(); ++s)
    for (uint32_t i = g.first[s]; i + 1 < g.first[s + 1]; ++i)
      t += "l " + std::to_string(i + 1) + " " + std::to_string(i + 2) + "\n";
  return t;
}

// One `l` a strand.
std::string objPolylines(const Groom& g) {
  std::string t = objVertices(g) + "s off\n";
  for (size_t s = 0; s < g.strandCount(); ++s) {
    t += "l";
    for (uint32_t i = g.first[s]; i < g.first[s + 1]; ++i)
      t.append(" ").append(std::to_string(i + 1));
    t += "\n";
  }
  return t;
}

void checkSame(const csm::io::GroomReadResult& r, const Groom& want) {
  INFO(r.error);
  REQUIRE(r.groom);
  CHECK(r.groom->first == want.first);
  CHECK(r.groom->points == want.points);
  CHECK(r.repair.empty());
}

std::string errorOf(const csm::io::GroomReadResult& r) {
  REQUIRE_FALSE(r.groom);
  return r.error;
}

}  // namespace

TEST_CASE("TressFX 3.x and 4.x files of the same strands read to the same points",
          "[io][tressfx][quick]") {
  const Groom g = sampleStrands();
  const auto three = csm::io::readTressFx(tressFx3(g, 8).bytes, "t3.tfx");
  const auto four = csm::io::readTressFx(tressFx4(g, 8).bytes, "t4.tfx");
  checkSame(three, g);
  checkSame(four, g);
  CHECK(three.groom->thickness == g.thickness);
  CHECK(four.groom->thickness == g.thickness);
  REQUIRE(three.groom->color.size() == 5);
  CHECK(three.groom->color[2] == glm::vec3(0.5f, 0.25f, 0.0f));
}

TEST_CASE("One groom in every format csmhair reads and writes reads back to the same strands",
          "[io][research][quick]") {
  // Coordinates no short decimal holds (a text writer must give every digit back), colour and
  // thickness on each strand; eight points a strand, as TressFX has them all alike.
  Groom g;
  for (int s = 0; s < 6; ++s) {
    std::vector<glm::vec3> pts;
    for (int i = 0; i < 8; ++i)
      pts.emplace_back(0.1f * float(s) + 0.0371f * std::sin(float(i)), 0.17f - 0.0233f * float(i),
                       -0.031f * float(s) + 1e-3f * std::cos(3.0f * float(i)));
    g.addStrand(pts);
    g.thickness.push_back(7e-5f * float(s + 1));
    g.color.emplace_back(0.2f * float(s % 5), 0.6f, 1.0f - 0.1f * float(s));
  }
  std::string problem;
  auto bytes = [&](std::optional<std::vector<std::byte>> b) {
    INFO(problem);
    REQUIRE(b);
    return *b;
  };
  const std::string obj = csm::io::encodeObjCurves(g);
  struct File {
    const char* name;
    std::vector<std::byte> bytes;
    bool keepsWidth, keepsColour;
  };
  const std::vector<File> files = {
      {"g.hair", bytes(csm::io::encodeCyHair(g, &problem)), true, true},
      {"g.tfx", tressFx3(g, 8).bytes, true, false},
      {"g4.tfx", tressFx4(g, 8).bytes, true, false},
      {"g.obj", std::vector<std::byte>(bytesOf(obj).begin(), bytesOf(obj).end()), false, false},
      {"g.data", bytes(csm::io::encodeStrandArrays(g, csm::io::kUscDataFloats, &problem)), false,
       false},
      {"g.bin", bytes(csm::io::encodeStrandArrays(g, csm::io::kCt2HairFloats, &problem)), false,
       false},
      {"g_ascii.ply", bytes(csm::io::encodePlyStrands(g, true, &problem)), true, true},
      {"g.ply", bytes(csm::io::encodePlyStrands(g, false, &problem)), true, true}};
  for (const File& f : files) {
    INFO(f.name);
    csm::io::GroomReadResult r;
    switch (csm::io::detectGroomFormat(f.name, f.bytes)) {
      case csm::io::GroomFormat::CyHair:
        r = csm::io::readCyHair(f.bytes, f.name);
        break;
      case csm::io::GroomFormat::TressFx:
        r = csm::io::readTressFx(f.bytes, f.name);
        break;
      case csm::io::GroomFormat::ObjCurves:
        r = csm::io::readObjCurves(f.bytes, f.name);
        break;
      case csm::io::GroomFormat::UscData:
        r = csm::io::readStrandArrays(f.bytes, f.name, csm::io::kUscDataFloats);
        break;
      case csm::io::GroomFormat::Ct2HairBin:
        r = csm::io::readStrandArrays(f.bytes, f.name, csm::io::kCt2HairFloats);
        break;
      case csm::io::GroomFormat::PlyStrands:
        r = csm::io::readPlyStrands(f.bytes, f.name);
        break;
      case csm::io::GroomFormat::TressFxProject:
      case csm::io::GroomFormat::Unknown:
        FAIL("not detected");
        break;
    }
    INFO(r.error);
    REQUIRE(r.groom);
    CHECK(r.repair.empty());
    REQUIRE(r.groom->first == g.first);
    double worst = 0.0;
    for (size_t i = 0; i < g.pointCount(); ++i)
      worst = std::max(worst, double(glm::length(r.groom->points[i] - g.points[i])) /
                                  double(glm::length(g.points[i])));
    CHECK(worst <= 1e-6);
    if (f.keepsWidth) {
      REQUIRE(r.groom->thickness.size() == g.strandCount());
      for (size_t s = 0; s < g.strandCount(); ++s)
        CHECK(r.groom->thickness[s] == Approx(g.thickness[s]).epsilon(1e-6));
    }
    if (f.keepsColour) {
      REQUIRE(r.groom->color.size() == g.strandCount());
      for (size_t s = 0; s < g.strandCount(); ++s)  // PLY's colour is a byte a channel
        CHECK(glm::length(r.groom->color[s] - g.color[s]) < 0.5f / 255.0f * 1.8f);
    }
  }
}

TEST_CASE("TressFX strands tied at both ends: the 3.x flag, 4.x inverse masses, the text keyword",
          "[io][tressfx][quick]") {
  const Groom g = sampleStrands();
  auto heldOf = [](const csm::io::GroomReadResult& r) {
    INFO(r.error);
    REQUIRE(r.groom);
    return r.groom->tipHeld;
  };
  const std::vector<uint8_t> none, all(5, 1);
  SECTION("3.x: bothEndsImmovable, a bool at byte 16, holds every strand's tip") {
    Binary f = tressFx3(g, 8);
    CHECK(heldOf(csm::io::readTressFx(f.bytes, "t.tfx")) == none);
    f.u32(16, 1);
    CHECK(heldOf(csm::io::readTressFx(f.bytes, "t.tfx")) == all);
    f.u32(16, 0xCDCDCD00u);  // a bool's padding as a debug heap leaves it: the bool is false
    CHECK(heldOf(csm::io::readTressFx(f.bytes, "t.tfx")) == none);
  }
  SECTION("4.x: a strand whose last vertex has inverse mass 0") {
    Binary f = tressFx4(g, 8);
    CHECK(heldOf(csm::io::readTressFx(f.bytes, "t.tfx")) == none);
    const uint32_t positions = 160;  // the first array appended after the header
    for (uint32_t s : {1u, 3u})
      for (uint32_t v : {6u, 7u}) f.f32(positions + 16 * (8 * s + v) + 12, 0.0f);
    CHECK(heldOf(csm::io::readTressFx(f.bytes, "t.tfx")) == std::vector<uint8_t>{0, 1, 0, 1, 0});
    // Every w 0: the file holds no masses (some tools leave w unset), not every tip.
    for (uint32_t v = 0; v < 40; ++v) f.f32(positions + 16 * v + 12, 0.0f);
    CHECK(heldOf(csm::io::readTressFx(f.bytes, "t.tfx")) == none);
  }
  SECTION("text: bothEndsImmovable 1, kept through a dropped strand") {
    const std::string header = "version 2.0\nbothEndsImmovable 1\n";
    CHECK(heldOf(csm::io::readTressFx(bytesOf(tressFxText(g, header)), "t.tfx")) == all);
    const auto r = csm::io::readTressFx(
        bytesOf(header + "numStrands 3\nstrand 0 numVerts 1\n0 0 0\nstrand 1 numVerts 2\n0 0 nan\n"
                         "1 1 1\nstrand 2 numVerts 2\n0 0 0\n1 1 1\n"),
        "t.tfx");
    CHECK(heldOf(r) == std::vector<uint8_t>{1});
    CHECK(heldOf(csm::io::readTressFx(bytesOf(tressFxText(g, "version 2\nbothEndsImmovable 0\n")),
                                      "t.tfx")) == none);
  }
}

TEST_CASE("TressFX 1.x and 2.x text files read, with the 2.x transform", "[io][tressfx][quick]") {
  const Groom g = sampleStrands();
  SECTION("1.x: no version line") {
    checkSame(csm::io::readTressFx(bytesOf(tressFxText(g, "")), "t1.tfx"), g);
  }
  SECTION("2.x: scale, rotation and translation as AMD's loader applies them") {
    const std::string header =
        "version 2.0\nscale 2\nrotation 0 1.5707963 0\ntranslation 1 2 3\n"
        "bothEndsImmovable 0\nmaxNumVerticesInStrand 64\nnumFollowHairsPerGuideHair 4\n"
        "maxRadiusAroundGuideHair 0.5\n";
    const auto r = csm::io::readTressFx(bytesOf(tressFxText(g, header)), "t2.tfx");
    INFO(r.error);
    REQUIRE(r.groom);
    REQUIRE(r.groom->points.size() == g.points.size());
    for (size_t i = 0; i < g.points.size(); ++i) {
      // A yaw of 90 degrees takes +z to +x: (x, y, z) -> (z, y, -x).
      const glm::vec3 p = 2.0f * g.points[i];
      const glm::vec3 want = glm::vec3(p.z, p.y, -p.x) + glm::vec3(1, 2, 3);
      CHECK(r.groom->points[i].x == Approx(want.x).margin(1e-4));
      CHECK(r.groom->points[i].y == Approx(want.y).margin(1e-4));
      CHECK(r.groom->points[i].z == Approx(want.z).margin(1e-4));
    }
  }
  SECTION("flaws: a one-vertex strand and a 1.#INF vertex drop their strands, named by line") {
    std::string t = tressFxText(g, "version 2.0\n");
    // Strand 1's first vertex line (line 13: 4 header lines and strand 0's 9) as Windows'
    // printf writes an infinity.
    const size_t at = t.find("strand 1 numVerts");
    const size_t vertex = t.find('\n', at) + 1;
    t.replace(vertex, t.find('\n', vertex) - vertex, "-1.#INF -1.#INF -1.#INF");
    const auto r = csm::io::readTressFx(bytesOf(t), "t.tfx");
    INFO(r.error);
    REQUIRE(r.groom);
    CHECK(r.groom->strandCount() == 4);
    CHECK(r.repair.droppedStrands == 1);
    REQUIRE(r.repair.notes.size() == 1);
    CHECK_THAT(r.repair.notes[0], Catch::Contains("t.tfx: line 14: strand 1 dropped: coordinate "
                                                  "x of point 0 is -inf"));
  }
  SECTION("notes name strands as the file numbers them, after a strand dropped for its size") {
    const auto r = csm::io::readTressFx(
        bytesOf("numStrands 3\nstrand 0 numVerts 1\n0 0 0\nstrand 1 numVerts 2\n0 0 nan\n1 1 1\n"
                "strand 2 numVerts 2\n0 0 0\n1 1 1\n"),
        "t.tfx");
    INFO(r.error);
    REQUIRE(r.groom);
    CHECK(r.groom->strandCount() == 1);
    REQUIRE(r.repair.notes.size() == 2);
    CHECK_THAT(r.repair.notes[0], Catch::Contains("t.tfx: line 2: strand 0 dropped: it has 1"));
    CHECK_THAT(r.repair.notes[1], Catch::Contains("t.tfx: line 5: strand 1 dropped: coordinate z"));
  }
  SECTION("refused, with the line") {
    CHECK_THAT(errorOf(csm::io::readTressFx(
                   bytesOf("version 2.0\nbothEndsImmovable yes\nnumStrands 1\n"), "t.tfx")),
               Catch::Contains("t.tfx:2: bothEndsImmovable: \"yes\" is not a number"));
    CHECK_THAT(errorOf(csm::io::readTressFx(bytesOf("version 2.0\nscale 1\n"), "t.tfx")),
               Catch::Contains("no \"numStrands\" line"));
    CHECK_THAT(errorOf(csm::io::readTressFx(
                   bytesOf("numStrands 2\nstrand 0 numVerts 2\n0 0 0\n1 1 1\n"), "t.tfx")),
               Catch::Contains("t.tfx:4: the file ends after 1 of the 2 strands"));
    CHECK_THAT(errorOf(csm::io::readTressFx(
                   bytesOf("numStrands 1\nstrand 0 numVerts 2\n0 0 0\n1 x 1\n"), "t.tfx")),
               Catch::Contains("t.tfx:4: a vertex: \"x\" is not a number"));
    CHECK_THAT(errorOf(csm::io::readTressFx(bytesOf("numStrands 1\nstrand zero\n"), "t.tfx")),
               Catch::Contains("t.tfx:2: expected \"strand 0 numVerts N\""));
  }
}

TEST_CASE("TressFX 3.x: every malformed header is refused with its byte", "[io][tressfx][quick]") {
  const Groom g = sampleStrands();
  Binary f = tressFx3(g, 8);
  auto error = [&] { return errorOf(csm::io::readTressFx(f.bytes, "t.tfx")); };
  SECTION("shorter than the header") {
    f.bytes.resize(200);
    CHECK_THAT(error(), Catch::Contains("t.tfx: byte 0: expected a 296-byte TressFX 3.x header, "
                                        "the data has only 200 bytes"));
  }
  SECTION("no strands") {
    f.u32(4, 0);
    CHECK_THAT(error(), Catch::Contains("byte 4: numGuideHairStrands is 0"));
  }
  SECTION("one vertex a strand") {
    f.u32(8, 1);
    CHECK_THAT(error(), Catch::Contains("byte 8: numVerticesPerStrand is 1"));
  }
  SECTION("no position array") {
    f.u32(144, 0);
    CHECK_THAT(error(), Catch::Contains("byte 144: verticesOffset is 0"));
  }
  SECTION("an array inside the header") {
    f.u32(148, 200);
    CHECK_THAT(error(), Catch::Contains("byte 148: strand thickness array offset 200 lies inside "
                                        "the 296-byte TressFX 3.x header"));
  }
  SECTION("an array past the end") {
    f.u32(164, uint32_t(f.bytes.size()) - 8);
    CHECK_THAT(error(), Catch::Contains("byte " + std::to_string(f.bytes.size() - 8) +
                                        ": vertex texture coordinate array of 320 bytes runs "
                                        "past end of file"));
  }
  SECTION("counts past the limit, before allocating") {
    f.u32(4, 0xFFFFFFFFu);
    f.u32(8, 0xFFFFFFFFu);
    CHECK_THAT(error(), Catch::Contains("byte 4:") && Catch::Contains("exceeds the limit"));
  }
  SECTION("a negative thickness") {
    std::vector<float> t = g.thickness;
    t[3] = -1.0f;
    f.u32(148, f.append(t));
    CHECK_THAT(error(), Catch::Contains(": thickness of strand 3 is -1"));
  }
  SECTION("a version between 3 and 4 is 3.x; any other is 4.x") {
    f.f32(0, 3.5f);
    CHECK(csm::io::readTressFx(f.bytes, "t.tfx").groom);
    f.f32(0, 4.0f);
    CHECK_THAT(error(), Catch::Contains("TressFX 4.x"));
  }
}

TEST_CASE("OBJ curves: Blender's edges and polylines read to the same strands",
          "[io][obj][quick]") {
  const Groom g = sampleStrands();
  checkSame(csm::io::readObjCurves(bytesOf(objEdges(g)), "edges.obj"), g);
  checkSame(csm::io::readObjCurves(bytesOf(objPolylines(g)), "lines.obj"), g);
  // Windows tools: a byte order mark, lines ending in CR LF.
  const std::string windows =
      "\xEF\xBB\xBF" + std::regex_replace(objPolylines(g), std::regex("\n"), "\r\n");
  checkSame(csm::io::readObjCurves(bytesOf(windows), "windows.obj"), g);
  checkSame(csm::io::readTressFx(bytesOf("\xEF\xBB\xBF" + tressFxText(g, "")), "bom.tfx"), g);
  SECTION("edges in any order and either direction, negative and v/vt indices, faces aside") {
    // Strand 0 as polyline pieces, backwards edges, relative indices, with a face and normals
    // that are not hair.
    std::string t = objVertices(g) + "vt 0 0\nvn 0 1 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n";
    t += "l 4/1 5/1 6/1 7/1 8/1\nl 2 1\nl 3 2\nl 3 4\n";  // strand 0, its start last
    for (size_t s = 1; s < g.strandCount(); ++s)
      for (uint32_t i = g.first[s]; i + 1 < g.first[s + 1]; ++i)
        t += "l " + std::to_string(i + 2) + " " + std::to_string(i + 1) + "\n";
    t += "l 1 1\nl 1 2\n";  // a point to itself, an edge again: read once
    const auto r = csm::io::readObjCurves(bytesOf(t), "mixed.obj");
    INFO(r.error);
    REQUIRE(r.groom);
    REQUIRE(r.groom->strandCount() == g.strandCount());
    CHECK_FALSE(r.rootsKnown);
    // Each strand is the same chain of points, from one end or the other.
    for (size_t s = 0; s < g.strandCount(); ++s) {
      std::vector<glm::vec3> a(r.groom->points.begin() + r.groom->first[s],
                               r.groom->points.begin() + r.groom->first[s + 1]);
      std::vector<glm::vec3> b(g.points.begin() + g.first[s], g.points.begin() + g.first[s + 1]);
      if (a.front() != b.front()) std::reverse(a.begin(), a.end());
      CHECK(a == b);
    }
  }
}

TEST_CASE("OBJ curves: what cannot be a strand is refused with its line", "[io][obj][quick]") {
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  auto error = [](const std::string& t) {
    return errorOf(csm::io::readObjCurves(bytesOf(t), "h.obj"));
  };
  CHECK_THAT(error(square + "l 1 2\nl 2 3\nl 2 4\n"),
             Catch::Contains("h.obj:7: vertex 2 (line 2) has a third edge here, after lines 5 and "
                             "6: a strand cannot branch"));
  CHECK_THAT(error(square + "l 1 2 3 4 1\n"),
             Catch::Contains("h.obj:5: the edges from this line close a loop"));
  CHECK_THAT(error(square + "l 1 2\nl 3 4\nl 4 1\nl 2 3\n"),
             Catch::Contains("h.obj:5: the edges from this line close a loop"));
  CHECK_THAT(
      error(square + "l 1 5\n"),
      Catch::Contains("h.obj:5: line element index 5 is out of range: 4 vertices before it"));
  CHECK_THAT(error(square + "l 0 1\n"), Catch::Contains("h.obj:5: line element index 0 is out"));
  CHECK_THAT(error(square + "l -5 1\n"), Catch::Contains("h.obj:5: line element index -5"));
  CHECK_THAT(error(square + "l 1\n"), Catch::Contains("h.obj:5: a line element needs at least 2"));
  CHECK_THAT(error("v 0 0\n"), Catch::Contains("h.obj:1: a vertex needs 3 coordinates"));
  CHECK_THAT(error("v 0 zero 0\n"), Catch::Contains("h.obj:1: vertex coordinate \"zero\""));
  CHECK_THAT(error(square + "f 1 2 3\n"), Catch::Contains("no line elements"));
  CHECK_THAT(error(square + "cstype bspline\ncurv 0 1 1 2 3 4\n"),
             Catch::Contains("h.obj:5: free-form curves (\"cstype\") are not read"));
  // A strand whose points are not all finite, or that goes nowhere, is dropped and said.
  const auto r = csm::io::readObjCurves(
      bytesOf(square + "v nan 0 0\nv 2 2 2\nv 2 2 2\nl 1 2\nl 5 4\nl 6 7\n"), "h.obj");
  INFO(r.error);
  REQUIRE(r.groom);
  CHECK(r.groom->strandCount() == 1);
  CHECK(r.repair.droppedStrands == 2);
  REQUIRE(r.repair.notes.size() == 2);
  CHECK_THAT(r.repair.notes[0], Catch::Contains("h.obj: line 5: strand 1 dropped: coordinate x"));
  CHECK_THAT(r.repair.notes[1], Catch::Contains("strand 2 dropped: all 2 points are equal"));
}

TEST_CASE("Groom repair: repeated and near points merge, short strands drop, all counted",
          "[io][repair][quick]") {
  Groom g;
  g.addStrand({{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, {0, 1, 0}, {0, 2, 0}});  // 2 repeats
  g.addStrand({{5, 0, 0}, {5, 0.001f, 0}});                              // 1 mm long
  g.addStrand({{9, 0, 0}, {9, 1, 0}, {9, 1.0000001f, 0}, {9, 2, 0}, {9, 2.00001f, 0}});
  g.color.assign(3, glm::vec3(0.5f));
  g.color[2] = glm::vec3(1.0f);
  SECTION("the first pass: equal points only") {
    Groom a = g;
    const auto r = csm::io::repairGroom(a, {});
    CHECK(r.droppedStrands == 0);
    CHECK(r.mergedPoints == 2);
    CHECK(a.strandSize(0) == 3);
    CHECK(a.strandSize(2) == 5);
    CHECK(r.summary() == "merged 2 points");
  }
  SECTION("the second pass: a length and a merge distance") {
    Groom a = g;
    csm::io::RepairOptions o;
    o.minLength = 0.01;
    o.mergeDistance = 0.001;
    const auto r = csm::io::repairGroom(a, o);
    CHECK(r.droppedStrands == 1);
    CHECK(r.mergedPoints == 4);
    REQUIRE(a.strandCount() == 2);
    CHECK(a.color.size() == 2);
    CHECK(a.color[1] == glm::vec3(1.0f));
    // The tip stays where the file has it; the point before it goes.
    CHECK(a.points.back() == glm::vec3(9, 2.00001f, 0));
    CHECK(a.strandSize(1) == 3);
    CHECK(r.summary() == "dropped 1 strand, merged 4 points");
  }
}
