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

#include <glm/geometric.hpp>

#include "sim/groom/groom_file.h"
#include "sim/run/grown_scene.h"
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
  // A sphere about the head's centre as the files have it (z turned, centimetres, 1.5 m up).
  project += "collision_sphere 3 150 -2 10\ncollision_capsule 0 140 0 0 130 0 6\n";
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
  // The file's strands are the guides, each with its piece's 4 follow hairs after them all.
  REQUIRE(report.fileGuides.size() == total);
  REQUIRE(report.followHairs == 4 * total);
  REQUIRE(g.strandCount() == 5 * total);
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

  // A follow hair's root lies within the piece's radius (0.5 file units) of its guide's, its
  // tip within twice that (tip separation 1), and it is not its guide.
  const double radius = 0.5 * double(report.fit.scale);
  double farRoot = 0.0, farTip = 0.0, nearTip = 1e30;
  for (size_t s = 0; s < total; ++s)
    for (size_t k = 0; k < 4; ++k) {
      const size_t f = total + 4 * s + k;
      farRoot = std::max(farRoot, double(glm::length(g.points[g.first[f]] - g.points[g.first[s]])));
      const double tip = glm::length(g.points[g.first[f + 1] - 1] - g.points[g.first[s + 1] - 1]);
      farTip = std::max(farTip, tip);
      nearTip = std::min(nearTip, tip);
    }
  INFO("radius " << radius << " m: roots up to " << farRoot << ", tips " << nearTip << " to "
                 << farTip);
  CHECK(farRoot < 1.1 * radius);
  CHECK(farTip < 2.2 * radius);
  CHECK(farTip > 0.5 * radius);

  // The project's sphere, where the fit put the groom: about the head's centre (as near as the fit
  // puts the groom where it was grown), 10 cm at the fit's scale.
  REQUIRE(report.fileSpheres.size() == 1);
  const Sphere sphere = report.fileSpheres[0];
  INFO("the sphere at " << sphere.center.x << " " << sphere.center.y << " " << sphere.center.z
                        << ", radius " << sphere.radius);
  CHECK(glm::length(sphere.center) < 0.04f);
  CHECK(std::abs(sphere.radius - 10.0f * report.fit.scale) < 1e-5f);
  CHECK(std::abs(sphere.radius - 0.1f) < 0.02f);

  const std::string text = groomReportText(report);
  CHECK(text.find("z mirrored") != std::string::npos);
  // The unit as the roots' size tells it: the pieces are in centimetres.
  CHECK(text.find("the file in about centimetres") != std::string::npos);
  CHECK(text.find("follow hairs drawn from") != std::string::npos);
  CHECK(text.find("stiffnessForLocalShapeMatching 0.9") != std::string::npos);
  // TressFX keeps 0.92 of the velocity a 60 Hz step: a rate of -60 ln 0.92 = 5.00 /s.
  CHECK(text.find("piece0.tfxsim: damping 0.08 is sim.damping 5.00 /s") != std::string::npos);
  CHECK(text.find("1 collision sphere,") != std::string::npos);
  CHECK(text.find("1 collision capsule:") != std::string::npos);

  SECTION("the scene simulates the file's guides and, on spheres, collides with its sphere") {
    c.collision.headShape = HeadShape::Spheres;
    GrownScene scene;
    REQUIRE(growScene(c, "", nullptr, {}, scene, &error));
    REQUIRE(scene.followers);
    CHECK(scene.followers->guideCount() == total);
    CHECK(scene.followers->drawn.strandCount() == 5 * total);
    REQUIRE(scene.head->spheres().size() == 1);
    const Sphere head = scene.head->spheres()[0];
    CHECK(glm::length(head.center - sphere.center) < 1e-4f);
    double worst = 0.0;
    for (size_t s = 0; s < scene.groom->strandCount(); ++s)
      worst = std::max(
          worst,
          std::abs(double(glm::length(scene.groom->points[scene.groom->first[s]] - head.center)) -
                   double(head.radius)));
    INFO("roots up to " << worst << " m from the project's sphere");
    CHECK(worst < 1e-3);
  }
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
  dir.write("sphere.tfxproj", "version 3.0\nnowhere.tfx 4 0.5 1\ncollision_sphere 0 1 2\n");
  const io::GroomReadResult sphere = io::readGroom((dir.path / "sphere.tfxproj").string());
  CHECK_FALSE(sphere.groom);
  CHECK(sphere.error.find("piece nowhere.tfx") != std::string::npos);
}

TEST_CASE("TressFX project: a bad follow-hair count or collision sphere is named with its line",
          "[io][tressfx][quick]") {
  Config c;
  c.hairstyle.strands = 60;
  ProjectDir dir;
  dir.write("front.tfx", test::tiedTressFx(pieces(c)[Front], 3, 12, false));
  for (const auto& [line, says] : std::vector<std::pair<std::string, std::string>>{
           {"front.tfx four 0.5 1", ":2: the follow-hair count \"four\""},
           {"front.tfx 65 0.5 1", ":2: the follow-hair count \"65\""},
           {"front.tfx 4 -1 1", ":2: the follow hairs' radius"},
           {"front.tfx 4 0.5 1\ncollision_sphere 0 1 2", ":3: collision_sphere wants four"},
           {"front.tfx 4 0.5 1\ncollision_sphere 0 1 2 0", ":3: the collision sphere's radius"}}) {
    dir.write("bad.tfxproj", "version 3.0\n" + line + "\n");
    const io::GroomReadResult r = io::readGroom((dir.path / "bad.tfxproj").string());
    INFO(line << " -> " << r.error);
    CHECK_FALSE(r.groom);
    CHECK(r.error.find("bad.tfxproj" + says) != std::string::npos);
  }
}
