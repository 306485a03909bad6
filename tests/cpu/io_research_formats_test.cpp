// The research data sets' formats (sim/groom/research_formats.h) against hand-made files: each
// layout a tool writes (PLY properties in any order, extra ones, big endian, nsegs of any integer
// type, edges instead of nsegs), and each flaw refused with its byte or line.
#include <cstring>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "sim/base/ply.h"
#include "sim/groom/groom_file.h"
#include "sim/groom/research_formats.h"

using csm::Groom;
using namespace csm::io;

namespace {

// Three strands of 3, 4 and 2 points.
Groom threeStrands() {
  Groom g;
  g.addStrand({{1, 2, 3}, {1, 3, 3}, {1, 4, 3.5f}});
  g.addStrand({{-1, 2, 0}, {-1, 1, 0}, {-1.5f, 0, 0}, {-2, -1, 0.25f}});
  g.addStrand({{0, 5, 0}, {0, 6, 1}});
  return g;
}

struct Bytes {
  std::vector<std::byte> b;
  template <class T>
  Bytes& put(T v, bool big = false) {
    std::byte raw[sizeof(T)];
    std::memcpy(raw, &v, sizeof(T));
    if (big)
      for (size_t i = 0; i < sizeof(T); ++i) b.push_back(raw[sizeof(T) - 1 - i]);
    else
      b.insert(b.end(), raw, raw + sizeof(T));
    return *this;
  }
  Bytes& text(const std::string& t) {
    for (const char c : t) b.push_back(std::byte(c));
    return *this;
  }
};

// A .data (3 floats a point) or .bin (7) file of the strands, as the data sets write them.
Bytes strandArrays(const Groom& g, int floats) {
  Bytes f;
  f.put(int32_t(g.strandCount()));
  for (size_t s = 0; s < g.strandCount(); ++s) {
    f.put(int32_t(g.strandSize(s)));
    for (uint32_t i = g.first[s]; i < g.first[s + 1]; ++i) {
      f.put(g.points[i].x).put(g.points[i].y).put(g.points[i].z);
      for (int k = 3; k < floats; ++k) f.put(0.5f);
    }
  }
  return f;
}

void sameStrands(const GroomReadResult& r, const Groom& want) {
  INFO(r.error);
  REQUIRE(r.groom);
  CHECK(r.groom->first == want.first);
  CHECK(r.groom->points == want.points);
}

std::string errorOf(const GroomReadResult& r) {
  REQUIRE_FALSE(r.groom);
  return r.error;
}

}  // namespace

TEST_CASE("USC-HairSalon .data and CT2Hair .bin read, one-point strands dropped and counted",
          "[io][research][quick]") {
  const Groom g = threeStrands();
  sameStrands(readStrandArrays(strandArrays(g, 3).b, "g.data", kUscDataFloats), g);
  sameStrands(readStrandArrays(strandArrays(g, 7).b, "g.bin", kCt2HairFloats), g);
  // HairSalon marks a scalp sample without hair by a strand of one point.
  Bytes f;
  f.put(int32_t(2)).put(int32_t(1)).put(0.0f).put(0.0f).put(0.0f);
  f.put(int32_t(2)).put(0.0f).put(0.0f).put(0.0f).put(0.0f).put(1.0f).put(0.0f);
  const GroomReadResult r = readStrandArrays(f.b, "bald.data", kUscDataFloats);
  REQUIRE(r.groom);
  CHECK(r.groom->strandCount() == 1);
  CHECK(r.repair.droppedStrands == 1);
  REQUIRE_FALSE(r.repair.notes.empty());
  CHECK_THAT(r.repair.notes[0],
             Catch::Contains("bald.data: byte 4: strand 0 dropped: it has 1 point"));
}

TEST_CASE(
    ".data and .bin: a truncated file, counts beyond it and trailing bytes are refused at "
    "their byte",
    "[io][research][quick]") {
  const Groom g = threeStrands();
  Bytes whole = strandArrays(g, 3);
  std::vector<std::byte> cut(whole.b.begin(), whole.b.end() - 5);
  CHECK_THAT(errorOf(readStrandArrays(cut, "cut.data", 3)),
             Catch::Contains("cut.data: byte 96: strand 2's 2 points (24 bytes") &&
                 Catch::Contains("run past the end of the file"));
  Bytes many = whole;
  int32_t lots = 1000000;
  std::memcpy(many.b.data(), &lots, 4);
  CHECK_THAT(
      errorOf(readStrandArrays(many.b, "many.data", 3)),
      Catch::Contains("many.data: byte 0: strand count 1000000 needs at least 4000004 bytes"));
  Bytes negative = whole;
  int32_t minus = -3;
  std::memcpy(negative.b.data() + 4, &minus, 4);
  CHECK_THAT(errorOf(readStrandArrays(negative.b, "neg.data", 3)),
             Catch::Contains("neg.data: byte 4: strand 0 has -3 points"));
  Bytes extra = whole;
  extra.put(1.0f);
  CHECK_THAT(errorOf(readStrandArrays(extra.b, "extra.data", 3)),
             Catch::Contains("extra.data: byte 124: 4 unexpected bytes after the last strand"));
  // A .data file read as .bin (7 floats a point) does not fit its own counts.
  CHECK_THAT(errorOf(readStrandArrays(whole.b, "g.bin", 7)), Catch::Contains("g.bin: byte "));
  CHECK_THAT(errorOf(readStrandArrays(std::vector<std::byte>(3), "tiny.data", 3)),
             Catch::Contains("tiny.data: byte 0: expected an int32 strand count"));
}

TEST_CASE(
    "Strand PLY: properties in any order, extra ones, colour, nsegs of any integer type, "
    "ASCII and both endians",
    "[io][research][ply][quick]") {
  const Groom g = threeStrands();
  const std::vector<uint8_t> red = {200, 10, 30};
  // z before x, a property csmhair does not use between them, colour, nsegs as int.
  const std::string header =
      "property float z\nproperty double confidence\nproperty float y\nproperty float x\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      "element strand 3\nproperty int nsegs\nend_header\n";
  std::string ascii =
      "ply\r\nformat ascii 1.0\r\ncomment CRLF in the header\nelement vertex 9\n" + header;
  for (size_t s = 0; s < 3; ++s)
    for (uint32_t i = g.first[s]; i < g.first[s + 1]; ++i) {
      const glm::vec3& p = g.points[i];
      ascii += std::to_string(p.z) + " 0.75 " + std::to_string(p.y) + "\t" + std::to_string(p.x) +
               " " + std::to_string(red[s]) + " 0 255\n";
    }
  ascii += "2\n3\n1\n";
  const GroomReadResult a = readPlyStrands(Bytes().text(ascii).b, "a.ply");
  sameStrands(a, g);
  REQUIRE(a.groom->color.size() == 3);
  CHECK(a.groom->color[0].x == Approx(200.0 / 255.0));
  CHECK(a.groom->color[2].z == Approx(1.0));

  for (const bool big : {false, true}) {
    INFO((big ? "big" : "little") << " endian, nsegs as uchar");
    Bytes f;
    f.text(std::string("ply\nformat binary_") + (big ? "big" : "little") +
           "_endian 1.0\nelement vertex 9\nproperty float z\nproperty double confidence\n"
           "property float y\nproperty float x\nelement strand 3\nproperty uchar nsegs\n"
           "end_header\n");
    for (const glm::vec3& p : g.points) f.put(p.z, big).put(0.75, big).put(p.y, big).put(p.x, big);
    f.put(uint8_t(2)).put(uint8_t(3)).put(uint8_t(1));
    sameStrands(readPlyStrands(f.b, "b.ply"), g);
  }
}

TEST_CASE("Strand PLY: an edge element instead of nsegs chains into the same strands",
          "[io][research][ply][quick]") {
  const Groom g = threeStrands();
  std::string t =
      "ply\nformat ascii 1.0\nelement vertex 9\nproperty float x\nproperty float y\n"
      "property float z\nelement edge 6\nproperty int vertex1\nproperty int vertex2\n"
      "end_header\n";
  for (const glm::vec3& p : g.points)
    t += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  // The edges in no particular order, some written tip to root.
  t += "6 5\n0 1\n7 8\n4 5\n2 1\n3 4\n";
  sameStrands(readPlyStrands(Bytes().text(t).b, "edges.ply"), g);
  // A vertex with a third edge is a branch.
  std::string branch = t;
  branch.replace(branch.find("element edge 6"), 14, "element edge 7");
  branch += "4 0\n";
  CHECK_THAT(errorOf(readPlyStrands(Bytes().text(branch).b, "branch.ply")),
             Catch::Contains("branch.ply: line") && Catch::Contains("a strand cannot branch"));
}

TEST_CASE("Strand PLY: what is not strands is refused with its line or byte",
          "[io][research][ply][quick]") {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
      "property float y\nproperty float z\nelement strand 2\n"
      "property ushort nsegs\nend_header\n";
  const std::string body = "0 0 0\n0 1 0\n1 0 0\n1 1 0\n1\n1\n";
  auto read = [](const std::string& t) { return readPlyStrands(Bytes().text(t).b, "s.ply"); };
  REQUIRE(read(head + body).groom);
  // Truncated: the file ends inside the strands.
  CHECK_THAT(
      errorOf(read(head + "0 0 0\n0 1 0\n1 0 0\n")),
      Catch::Contains("s.ply:12: the file ends inside row 3 of the 4 of element \"vertex\""));
  // nsegs that run past the vertices.
  CHECK_THAT(errorOf(read(head + "0 0 0\n0 1 0\n1 0 0\n1 1 0\n1\n5\n")),
             Catch::Contains("s.ply: line 15: strand 1 ends at vertex 8, past the 4 vertices"));
  // A token that is not a number of its type, with its line.
  CHECK_THAT(errorOf(read(head + "0 0 0\n0 one 0\n1 0 0\n1 1 0\n1\n1\n")),
             Catch::Contains("s.ply:11: the value \"one\" of property \"y\"") &&
                 Catch::Contains("not a number of type float"));
  CHECK_THAT(errorOf(read(head + "0 0 0\n0 1 0\n1 0 0\n1 1 0\n1.5\n1\n")),
             Catch::Contains("s.ply:14:") && Catch::Contains("an integer of type ushort"));
  // No way to tell the strands apart.
  CHECK_THAT(errorOf(read("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                          "property float y\nproperty float z\nend_header\n0 0 0\n")),
             Catch::Contains("s.ply: header: no element \"strand\" with nsegs"));
  // Header flaws.
  CHECK_THAT(errorOf(read("ply\nformat binary_middle_endian 1.0\nend_header\n")),
             Catch::Contains("s.ply:2: unknown PLY format \"binary_middle_endian\""));
  CHECK_THAT(errorOf(read("ply\nformat ascii 1.0\nelement vertex 2\nproperty float3 x\n")),
             Catch::Contains("s.ply:4: unknown type \"float3\""));
  CHECK_THAT(errorOf(read("ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n")),
             Catch::Contains("s.ply:4: the file ends before end_header"));
  // A binary count beyond the file, refused before anything is allocated.
  Bytes f;
  f.text(
      "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n");
  f.put(1.0f);
  CHECK_THAT(errorOf(readPlyStrands(f.b, "big.ply")),
             Catch::Contains("big.ply:3: element \"vertex\" has 4000000000 rows"));
  // Rows without a property, and a count no PLY file holds (a fuzzed header read each empty row).
  CHECK_THAT(errorOf(read("ply\nformat binary_little_endian 1.0\nelement vertex 800000000\n"
                          "end_header\n")),
             Catch::Contains("s.ply:3: element \"vertex\" has 800000000 rows but no property"));
  CHECK_THAT(errorOf(read("ply\nformat ascii 1.0\nelement vertex 80000000000000000000000\n")),
             Catch::Contains("s.ply:3: expected \"element NAME COUNT\" with a count from 0"));
  // Trailing bytes after the last element.
  Bytes t;
  t.text(
      "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n"
      "property float y\nproperty float z\nelement strand 1\nproperty uchar nsegs\n"
      "end_header\n");
  const auto bodyAt = t.b.size();
  t.put(0.0f).put(0.0f).put(0.0f).put(0.0f).put(1.0f).put(0.0f).put(uint8_t(1)).put(uint8_t(9));
  CHECK_THAT(errorOf(readPlyStrands(t.b, "tail.ply")),
             Catch::Contains("tail.ply: byte " + std::to_string(bodyAt + 25) +
                             ": 1 bytes after the last element"));
}

TEST_CASE("Groom files: .data, .bin and .ply detected and refused by name when unknown",
          "[io][research][quick]") {
  const std::vector<std::byte> none;
  CHECK(detectGroomFormat("a.DATA", none) == GroomFormat::UscData);
  CHECK(detectGroomFormat("a.bin", none) == GroomFormat::Ct2HairBin);
  CHECK(detectGroomFormat("a.ply", none) == GroomFormat::PlyStrands);
  // A PLY by its first line whatever its name.
  CHECK(detectGroomFormat("hair.strands", Bytes().text("ply\nformat ascii 1.0\n").b) ==
        GroomFormat::PlyStrands);
  CHECK(isWritableGroomName("out.data"));
  CHECK(isWritableGroomName("out_ascii.ply"));
}
