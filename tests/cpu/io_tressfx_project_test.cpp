// A TressFX project of our own making, as AMD's exporters write one: four pieces (front, the two
// sides, back) and a tail, left-handed with the face toward -z, in centimetres, opened through
// its .tfxproj and fitted as one groom: the front on the forehead, the back and tail behind, the
// left side at the character's left; what csmhair does not use said.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "sim/groom/groom_file.h"
#include "tests/import_cases.h"

using namespace csm;
namespace fs = std::filesystem;

namespace {

struct ProjectDir {
  fs::path path;
  ProjectDir() {
    path = fs::temp_directory_path() / ("csm_tfxproj_" + std::to_string(::getpid()));
    fs::create_directories(path);
  }
  ~ProjectDir() { fs::remove_all(path); }
  void write(const std::string& name, const std::vector<std::byte>& bytes) const {
    std::ofstream(path / name, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name, std::ios::binary) << text;
  }
};

enum Piece { Front, Left, Right, Back, Tail, Pieces };
const char* const kNames[Pieces] = {"front_top.tfx", "side_left.tfx", "side_right.tfx", "back.tfx",
                                    "tail.tfx"};

// The scene's hairstyle cut into pieces by where each root is (head frame: face +z, the
// character's left +x), and a tail hanging from a tie behind the head; then as a left-handed
// file has it: z turned, centimetres, 1.5 m up.
std::vector<Groom> pieces(const Config& c) {
  const Groom grown = growHairstyle(c, *HeadModel::require(c));
  std::vector<Groom> out(Pieces);
  auto add = [&](Piece p, std::vector<glm::vec3> pts) {
    for (glm::vec3& q : pts) q = test::toFile(glm::vec3(q.x, q.y, -q.z));
    out[p].addStrand(pts);
  };
  for (size_t s = 0; s < grown.strandCount(); ++s) {
    std::vector<glm::vec3> pts(grown.points.begin() + grown.first[s],
                               grown.points.begin() + grown.first[s + 1]);
    const glm::vec3 root = pts.front();
    const Piece p = root.z > 0.04f ? Front : root.z < -0.03f ? Back : root.x > 0.0f ? Left : Right;
    add(p, pts);
    if (p == Back && out[Tail].strandCount() < 40) {
      std::vector<glm::vec3> tail;
      const glm::vec3 tie(0.3f * root.x, 0.02f, -0.125f);
      for (int k = 0; k < 12; ++k) tail.push_back(tie + glm::vec3(0.0f, -0.02f * k, -0.004f * k));
      add(Tail, tail);
    }
  }
  return out;
}

glm::vec3 meanRoot(const Groom& g, size_t from, size_t count) {
  glm::vec3 sum(0.0f);
  for (size_t s = from; s < from + count; ++s) sum += g.points[g.first[s]];
  return sum / float(count);
}

}  // namespace

TEST_CASE(
    "TressFX project: five left-handed pieces open as one groom, the front on the forehead, the "
    "back and tail behind, the left at the left",
    "[io][tressfx][quick]") {
  Config c;
  c.hairstyle.strands = 300;
  const std::vector<Groom> parts = pieces(c);
  ProjectDir dir;
  std::string project = "version 3.0\r\nproject_name ours\r\n# a comment\r\n";
  for (int p = 0; p < Pieces; ++p) {
    REQUIRE(parts[p].strandCount() > 0);
    dir.write(kNames[p], test::tiedTressFx(parts[p], p == Tail ? 4 : 3, 12, false));
    project += std::string(kNames[p]) + " 4 0.5 1 piece" + std::to_string(p) + ".tfxsim Piece\r\n";
  }
  dir.write("piece0.tfxsim", "version 3.0\nstiffnessForLocalShapeMatching 0.9\ndamping 0.08\n");
  project += "collision_sphere 0 160 0 11\ncollision_capsule 0 140 0 0 130 0 6\n";
  dir.write("ours.tfxproj", project);

  c.hairstyle.file = (dir.path / "ours.tfxproj").string();
  c.hairstyle.strands = 1000000;
  Groom g;
  std::string error;
  GroomReport report;
  REQUIRE(buildGroom(c, *HeadModel::require(c), "", g, &error, &report));
  INFO(error);
  size_t total = 0;
  for (const Groom& p : parts) total += p.strandCount();
  REQUIRE(g.strandCount() == total);
  CHECK(report.mirrored);
  CHECK(report.facingNote.empty());

  glm::vec3 mean[Pieces];
  for (size_t p = 0, at = 0; p < Pieces; at += parts[p].strandCount(), ++p)
    mean[p] = meanRoot(g, at, parts[p].strandCount());
  INFO("front " << mean[Front].z << ", back " << mean[Back].z << ", tail " << mean[Tail].z
                << ", left x " << mean[Left].x << ", right x " << mean[Right].x);
  CHECK(mean[Front].z > 0.03f);  // the forehead: the face is +z
  CHECK(mean[Back].z < -0.03f);
  CHECK(mean[Tail].z < -0.05f);
  CHECK(mean[Left].x > 0.03f);  // the character's left
  CHECK(mean[Right].x < -0.03f);
  // Fitted together: the pieces keep their places against each other (one scale for all).
  CHECK(mean[Front].y > mean[Tail].y);

  const std::string text = groomReportText(report);
  CHECK(text.find("z mirrored") != std::string::npos);
  CHECK(text.find("4 follow hairs a guide") != std::string::npos);
  CHECK(text.find("stiffnessForLocalShapeMatching 0.9") != std::string::npos);
  CHECK(text.find("2 collision shapes") != std::string::npos);
}

TEST_CASE("TressFX project: a missing piece is named with the project's line",
          "[io][tressfx][quick]") {
  ProjectDir dir;
  dir.write("broken.tfxproj", "version 3.0\nproject_name broken\n\nnowhere.tfx 4 0.5 1\n");
  const io::GroomReadResult r = io::readGroom((dir.path / "broken.tfxproj").string());
  CHECK_FALSE(r.groom);
  CHECK(r.error.find("broken.tfxproj:4: piece nowhere.tfx") != std::string::npos);
  dir.write("empty.tfxproj", "version 3.0\nproject_name empty\n");
  const io::GroomReadResult e = io::readGroom((dir.path / "empty.tfxproj").string());
  CHECK_FALSE(e.groom);
  CHECK(e.error.find("no piece") != std::string::npos);
}
