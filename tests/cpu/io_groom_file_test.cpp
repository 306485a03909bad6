// Groom files on disk: format detection, the atomic cyHair write, OBJ curves out, a file round
// trip.
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <catch2/catch.hpp>

#include "sim/groom/cyhair.h"
#include "sim/groom/groom_file.h"
#include "sim/groom/obj_curves.h"

namespace fs = std::filesystem;
using csm::Groom;
using csm::io::GroomFormat;

namespace {

// A fresh directory per test case, removed afterwards.
struct TempDir {
  fs::path path;
  TempDir() {
    static int counter = 0;
    path = fs::temp_directory_path() /
           ("csm_io_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
  std::string file(const std::string& name) const { return (path / name).string(); }
};

Groom sampleGroom() {
  Groom groom;
  for (int s = 0; s < 20; ++s) {
    std::vector<glm::vec3> strand;
    for (int i = 0; i < 10 + s; ++i) strand.push_back({0.01f * s, 0.1f - 0.01f * i, 0.001f * i});
    groom.addStrand(strand);
  }
  return groom;
}

void writeBytes(const std::string& path, const std::vector<std::byte>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

TEST_CASE("Groom files: write, read back through the dispatcher", "[io][groom_file][quick]") {
  TempDir dir;
  const std::string path = dir.file("groom.hair");
  const Groom groom = sampleGroom();
  std::string error;
  REQUIRE(csm::io::writeGroom(path, groom, &error));
  CHECK_FALSE(fs::exists(path + ".tmp" + std::to_string(::getpid())));

  const auto result = csm::io::readGroom(path);
  INFO(result.error);
  REQUIRE(result.groom);
  CHECK(result.groom->first == groom.first);
  REQUIRE(result.groom->points.size() == groom.points.size());
  CHECK(std::memcmp(result.groom->points.data(), groom.points.data(),
                    groom.points.size() * sizeof(glm::vec3)) == 0);

  SECTION("overwriting replaces the file whole") {
    Groom other;
    other.addStrand({{0, 0, 0}, {0, -1, 0}});
    REQUIRE(csm::io::writeCyHair(path, other, &error));
    const auto again = csm::io::readGroom(path);
    REQUIRE(again.groom);
    CHECK(again.groom->strandCount() == 1);
  }
  SECTION("a failed write leaves the old file alone") {
    Groom broken = groom;
    broken.first.back() += 1;
    CHECK_FALSE(csm::io::writeGroom(path, broken, &error));
    CHECK_THAT(error, Catch::StartsWith(path));
    CHECK(csm::io::readGroom(path).groom);
  }
  SECTION("a missing directory is an error, not a crash") {
    CHECK_FALSE(csm::io::writeGroom(dir.file("no/such/dir/g.hair"), groom, &error));
    CHECK_FALSE(error.empty());
  }
}

TEST_CASE("Groom files: format detection", "[io][groom_file][quick]") {
  const auto hair = csm::io::encodeCyHair(sampleGroom(), nullptr);
  REQUIRE(hair);
  CHECK(csm::io::detectGroomFormat("x.hair", *hair) == GroomFormat::CyHair);
  CHECK(csm::io::detectGroomFormat("x.bin", *hair) == GroomFormat::CyHair);  // by signature
  CHECK(csm::io::detectGroomFormat("x.TFX", {}) == GroomFormat::TressFx);
  CHECK(csm::io::detectGroomFormat("x.hair", {}) == GroomFormat::CyHair);
  CHECK(csm::io::detectGroomFormat("x.obj", {}) == GroomFormat::ObjCurves);
  CHECK(csm::io::detectGroomFormat("x.stl", {}) == GroomFormat::Unknown);
  const std::string text = "version 2.0\nnumStrands 1\n";
  CHECK(csm::io::detectGroomFormat("x.txt", std::as_bytes(std::span(text.data(), text.size()))) ==
        GroomFormat::TressFx);

  TempDir dir;
  SECTION("signature wins over the extension") {
    writeBytes(dir.file("renamed.dat"), *hair);
    CHECK(csm::io::readGroom(dir.file("renamed.dat")).groom);
  }
  SECTION("a .hair file without the signature reports the signature") {
    std::vector<std::byte> bad = *hair;
    bad[0] = std::byte{'X'};
    writeBytes(dir.file("bad.hair"), bad);
    const auto result = csm::io::readGroom(dir.file("bad.hair"));
    CHECK_THAT(result.error, Catch::Contains("bad.hair: byte 0: expected the signature"));
  }
  SECTION("a .tfx file goes to the TressFX reader") {
    writeBytes(dir.file("short.tfx"), std::vector<std::byte>(10));
    const auto result = csm::io::readGroom(dir.file("short.tfx"));
    CHECK_THAT(result.error, Catch::Contains("short.tfx: byte 0: expected a 160-byte TressFX"));
  }
  SECTION("unknown formats and missing files are errors") {
    writeBytes(dir.file("mesh.stl"), std::vector<std::byte>(200));
    CHECK_THAT(csm::io::readGroom(dir.file("mesh.stl")).error,
               Catch::Contains("unknown groom format"));
    CHECK_THAT(csm::io::readGroom(dir.file("missing.hair")).error,
               Catch::Contains("missing.hair: not a readable file"));
    CHECK_FALSE(csm::io::writeGroom(dir.file("out.tfx"), sampleGroom(), nullptr));
  }
}

TEST_CASE("Groom files: OBJ curves written as Blender reads them, read back to the same strands",
          "[io][groom_file][quick]") {
  TempDir dir;
  Groom groom = sampleGroom();
  groom.points[3] = {0.1f / 3.0f, -1e-7f, 0.0123456789f};  // floats whose text must round-trip
  const std::string text = csm::io::encodeObjCurves(groom);
  // One `v` a point and one `l i j` an edge, two indices each, root to tip, strand after strand.
  size_t vertices = 0, edges = 0;
  bool twoIndices = true, inOrder = true;
  size_t expectFrom = 1;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream t(line);
    std::string keyword;
    t >> keyword;
    if (keyword == "v") ++vertices;
    if (keyword != "l") continue;
    std::vector<size_t> index;
    for (size_t i; t >> i;) index.push_back(i);
    twoIndices = twoIndices && index.size() == 2;
    if (index.size() != 2) continue;
    // The next strand starts one point on: its root is not joined to the last tip.
    while (expectFrom < groom.pointCount() && index[0] != expectFrom) ++expectFrom;
    inOrder = inOrder && index[0] == expectFrom && index[1] == expectFrom + 1;
    ++expectFrom;
    ++edges;
  }
  CHECK(vertices == groom.pointCount());
  CHECK(edges == groom.pointCount() - groom.strandCount());
  CHECK(twoIndices);
  CHECK(inOrder);
  // Through the file and the dispatcher: every strand, every point to the float, root first.
  const std::string path = dir.file("frame.obj");
  std::string error;
  REQUIRE(csm::io::writeGroom(path, groom, &error));
  const csm::io::GroomReadResult back = csm::io::readGroom(path);
  REQUIRE(back.error.empty());
  REQUIRE(back.groom);
  REQUIRE(back.groom->first == groom.first);
  CHECK(std::memcmp(back.groom->points.data(), groom.points.data(),
                    groom.points.size() * sizeof(glm::vec3)) == 0);
  // Any case of the extension; nothing else.
  CHECK(csm::io::isWritableGroomName("A.OBJ"));
  CHECK(csm::io::isWritableGroomName("a.Hair"));
  CHECK_FALSE(csm::io::isWritableGroomName("a.tfx"));
  CHECK_FALSE(csm::io::writeGroom(dir.file("out.abc"), groom, &error));
  CHECK_THAT(error, Catch::Contains("out.abc: can only write cyHair (.hair), OBJ curves (.obj)"));
  // Each research format through the file: written whole, read back by its name.
  for (const char* name : {"out.data", "out.bin", "out.ply", "out_ascii.ply"}) {
    INFO(name);
    REQUIRE(csm::io::writeGroom(dir.file(name), groom, &error));
    const auto r = csm::io::readGroom(dir.file(name));
    INFO(r.error);
    REQUIRE(r.groom);
    CHECK(r.groom->first == groom.first);
    CHECK(r.groom->points == groom.points);
  }
}
