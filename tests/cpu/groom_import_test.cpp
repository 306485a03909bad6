// Grooms from files as a scene takes them (sim/groom/scene_groom.h's fitFileGroom): the flaws of
// real grooms repaired and counted, steps that a few degenerate strands cannot set, roots on the
// scalp of any head and no particle inside it, roots found for OBJ curves.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <catch2/catch.hpp>

#include "sim/solver/cpu_solver.h"
#include "sim/head/distance_grid.h"
#include "sim/head/mannequin.h"
#include "sim/head/head_model.h"
#include "sim/groom/groom_file.h"
#include "sim/groom/hairstyle.h"
#include "sim/solver/stiffness.h"
#include "tests/import_cases.h"
#include "sim/verify/solver_head.h"

using namespace csm;
namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("csm_import_" + std::to_string(::getpid()));
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name, std::ios::binary) << text;
    return (path / name).string();
  }
};

// Signed distance to the scene's head: its field, or the nearest sphere.
double headDistance(const HeadModel& head, const glm::vec3& p) {
  if (const DistanceGrid* field = head.field()) return field->sample(glm::dvec3(p));
  double d = 1e30;
  for (const Sphere& s : head.spheres())
    d = std::min(d, double(glm::length(p - s.center)) - double(s.radius));
  return d;
}

// A closed octahedron of 12 cm about the head's centre: an OBJ head of someone's own.
std::string octahedron() {
  return "v 0.12 0 0\nv -0.12 0 0\nv 0 0.12 0\nv 0 -0.12 0\nv 0 0 0.12\nv 0 0 -0.12\n"
         "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
}

// A data set's frame: y up, the face toward +x, in centimetres, the head 1.5 m up.
glm::vec3 toDataSet(const glm::vec3& metres) {
  const glm::dmat3 facePlusX(glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0));
  return glm::vec3(facePlusX * glm::dvec3(metres) * 100.0 + glm::dvec3(3.0, 150.0, -7.0));
}

// The mannequin's head as a data set ships it beside its grooms, in toDataSet's frame.
std::string dataSetHead() {
  const SurfaceMesh& m = mannequinHeadMesh();
  std::ostringstream s;
  s.precision(9);
  for (const glm::vec3& p : m.positions) {
    const glm::vec3 q = toDataSet(p);
    s << "v " << q.x << " " << q.y << " " << q.z << "\n";
  }
  for (size_t i = 0; i < m.indices.size(); i += 3)
    s << "f " << m.indices[i] + 1 << " " << m.indices[i + 1] + 1 << " " << m.indices[i + 2] + 1
      << "\n";
  return s.str();
}

}  // namespace

TEST_CASE(
    "Import: a data set's groom beside its own head is kept where the file put it on that head",
    "[import][head_fit][quick]") {
  TempDir dir;
  Config c;
  c.hairstyle.strands = 200;
  c.collision.headShape = HeadShape::Sdf;
  // Grown on the mannequin, then written in the data set's frame with the head beside it.
  const Groom grown = growHairstyle(c, *HeadModel::require(c));
  Groom file = grown;
  for (glm::vec3& p : file.points) p = toDataSet(p);
  const std::string groomPath = (dir.path / "groom.data").string();
  REQUIRE(io::writeGroom(groomPath, file));
  Config scene = c;
  scene.head.mesh = dir.write("head.obj", dataSetHead());
  scene.hairstyle.file = groomPath;
  const std::shared_ptr<const HeadModel> head = HeadModel::require(scene);
  REQUIRE(head->meshFit());
  INFO(head->meshFit()->text());
  REQUIRE(head->meshFit()->unit == "cm");

  auto build = [&](const Config& s, GroomReport& report) {
    Groom g;
    std::string error;
    REQUIRE(buildGroom(s, *head, "", g, &error, &report));
    REQUIRE(g.strandCount() == grown.strandCount());
    double far = 0.0;
    for (size_t k = 0; k < g.strandCount(); ++k)
      far = std::max(far, double(glm::length(g.points[g.first[k]] - grown.points[grown.first[k]])));
    return far;
  };
  GroomReport report;
  const double kept = build(scene, report);
  INFO(groomReportText(report));
  CHECK(report.keptOnHead);
  CHECK_THAT(report.placeNote, Catch::Contains("kept where the file put it"));
  // Every root where it grew, to the head fit's accuracy (tests/cpu/head_fit_test.cpp: 3 mm).
  CHECK(kept < 4e-3);

  // Fitted onto the head as any groom is, when the preset says so.
  Config fitted = scene;
  fitted.hairstyle.importPlace = ImportPlace::Fit;
  GroomReport fitReport;
  build(fitted, fitReport);
  CHECK_FALSE(fitReport.keptOnHead);
  CHECK(fitReport.placeNote.empty());

  // A groom 10 cm off the head is not its own: fitted, and said.
  for (glm::vec3& p : file.points) p.z += 10.0f;
  REQUIRE(io::writeGroom(groomPath, file));
  GroomReport offReport;
  build(scene, offReport);
  CHECK_FALSE(offReport.keptOnHead);
  CHECK_THAT(offReport.placeNote, Catch::Contains("not on it"));

  // Kept on a head there is not: refused, with the setting named.
  Config noHead = c;
  noHead.hairstyle.file = groomPath;
  noHead.hairstyle.importPlace = ImportPlace::Head;
  Groom g;
  std::string error;
  CHECK_FALSE(buildGroom(noHead, *HeadModel::require(noHead), "", g, &error));
  CHECK_THAT(error, Catch::Contains("hairstyle.import_place") && Catch::Contains("head.mesh"));
}

TEST_CASE(
    "Import: a groom of normal strands and three degenerate ones runs at the normal "
    "strands' steps",
    "[import][stiffness][quick]") {
  Config c;
  c.hairstyle.strands = 150;
  c.collision.headShape = HeadShape::Sdf;
  const Groom clean = test::importFor(c, test::importedGroom(c, false));
  GroomReport report;
  const Groom flawed = test::importFor(c, test::importedGroom(c, true), &report);
  // The 7.5 um strand and the repeated point are dropped, the 1 um points merged; the 1.5 cm
  // strand is kept.
  CHECK(report.repair.droppedStrands == 2);
  CHECK(report.repair.mergedPoints == 6 * 150);
  REQUIRE(flawed.strandCount() == clean.strandCount() + 1);
  CHECK_THAT(groomReportText(report), Catch::Contains("dropped 2 strands, merged 900 points"));

  const Pose pose;
  const Regions regions = buildRegions(makeHairState(flawed, c.sim, pose), c.sim);
  // The short strand alone would ask for more steps than the rest.
  CHECK(planFrame(c.sim, regions.maxRate).wanted > 2 * planFrame(c.sim, regions.planRate).wanted);

  CpuSolver a, b;
  resetWithHead(a, clean, c, pose);
  resetWithHead(b, flawed, c, pose);
  CHECK(b.stiffness().plan.substeps == a.stiffness().plan.substeps);
  CHECK(b.stiffness().stifferStrands == 1);
  CHECK(a.stiffness().stifferStrands == 0);
  CHECK_THAT(stiffnessWarning(b.stiffness()),
             Catch::Contains("1 of 151 strands") && Catch::Contains("alpha = 1"));
}

TEST_CASE("Import: roots land on the scalp of every head, and no particle starts inside it",
          "[import][quick]") {
  TempDir dir;
  Config grownOn;
  grownOn.hairstyle.strands = 120;
  // Every point 1.5 cm towards the head's centre: the file's strands start deep in the scalp.
  Groom file = test::importedGroom(grownOn, false);
  const glm::vec3 centre = test::toFile(glm::vec3(0.0f));
  for (glm::vec3& p : file.points) p -= 1.5f * glm::normalize(p - centre);

  for (const std::string head : {"spheres", "mannequin", "obj"}) {
    DYNAMIC_SECTION(head) {
      Config c = grownOn;
      c.collision.headShape = head == "spheres" ? HeadShape::Spheres : HeadShape::Sdf;
      if (head == "obj") {
        c.head.mesh = dir.write("octahedron.obj", octahedron());
        // In the head frame already, in metres (no cranium to infer a unit from).
        c.head.meshScale = 1.0f;
        c.head.meshPlace = false;
        REQUIRE(HeadModel::require(c)->field() != &mannequinGrid());
      }
      GroomReport report;
      const Groom g = test::importFor(c, file, &report);
      if (head != "spheres") CHECK(report.pushedParticles > 0);  // spheres: the snap suffices
      size_t inside = 0;
      double worstRoot = 0.0;
      const std::shared_ptr<const HeadModel> model = HeadModel::require(c);
      for (size_t s = 0; s < g.strandCount(); ++s) {
        worstRoot = std::max(worstRoot, std::abs(headDistance(*model, g.points[g.first[s]])));
        for (uint32_t i = g.first[s] + 1; i < g.first[s + 1]; ++i)
          inside += headDistance(*model, g.points[i]) < 0.0;
      }
      // Particles pushed from inside onto one surface point are merged: no segment is shorter
      // than the import's merge distance.
      double shortest = 1e30;
      for (size_t s = 0; s < g.strandCount(); ++s)
        for (uint32_t i = g.first[s] + 1; i < g.first[s + 1]; ++i)
          shortest = std::min(shortest, double(glm::length(g.points[i] - g.points[i - 1])));
      INFO(head << ": roots up to " << worstRoot << " m from the surface, " << inside
                << " particles inside, " << report.pushedParticles
                << " pushed out, the shortest segment " << shortest << " m");
      CHECK(worstRoot < 1e-3);
      CHECK(inside == 0);
      CHECK(shortest > kMergeShare * double(c.hairstyle.segmentLength));
    }
  }
}

TEST_CASE("Import: OBJ curves written tip first are turned root first", "[import][obj][quick]") {
  TempDir dir;
  Config c;
  c.hairstyle.strands = 80;
  c.collision.headShape = HeadShape::Sdf;
  const Groom file = test::importedGroom(c, false);
  // Polylines: strands 0, 10, 20, ... tip first (a tool that wrote some strands backwards).
  std::string obj;
  for (const glm::vec3& p : file.points)
    obj +=
        "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  size_t reversed = 0;
  for (size_t s = 0; s < file.strandCount(); ++s) {
    obj += "l";
    const bool back = s % 10 == 0;
    reversed += back;
    for (uint32_t k = 0; k < file.strandSize(s); ++k)
      obj.append(" ").append(std::to_string(back ? file.first[s + 1] - k : file.first[s] + k + 1));
    obj += "\n";
  }
  c.hairstyle.file = dir.write("tips_first.obj", obj);
  Groom g;
  std::string error;
  GroomReport report;
  const std::shared_ptr<const HeadModel> model = HeadModel::require(c);
  REQUIRE(buildGroom(c, *model, "", g, &error, &report));
  CHECK(report.turnedStrands == reversed);
  // Every root is on the scalp, where the file grew it.
  const Groom rootFirst = test::importFor(c, file);
  REQUIRE(g.strandCount() == rootFirst.strandCount());
  for (size_t s = 0; s < g.strandCount(); ++s) {
    CHECK(std::abs(headDistance(*model, g.points[g.first[s]])) < 1e-3);
    CHECK(glm::length(g.points[g.first[s]] - rootFirst.points[rootFirst.first[s]]) < 1e-3f);
  }
  // A whole file written tip first, too.
  std::string allBack;
  for (const glm::vec3& p : file.points)
    allBack +=
        "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  for (size_t s = 0; s < file.strandCount(); ++s)
    for (uint32_t k = file.first[s + 1] - 1; k > file.first[s]; --k)
      allBack += "l " + std::to_string(k + 1) + " " + std::to_string(k) + "\n";
  c.hairstyle.file = dir.write("all_back.obj", allBack);
  REQUIRE(buildGroom(c, *HeadModel::require(c), "", g, &error, &report));
  CHECK(report.turnedStrands == file.strandCount());
}

TEST_CASE("Import: the flawed groom's 30 frames on the CPU reference", "[import][cpu][quick]") {
  CpuSolver cpu;
  test::checkImportedRun(cpu, 1e-9);
}

TEST_CASE(
    "Import: TressFX 3.x and 4.x strands tied at both ends keep both with the nodding head, CPU",
    "[import][cpu][quick]") {
  for (int version : {3, 4}) {
    CpuSolver cpu;
    test::checkHeldEnds(cpu, 1e-6, version);
  }
}

TEST_CASE(
    "Import: a ponytail's back tied at both ends, fitted through a larger head, stays within the "
    "strain limit while nodding, CPU",
    "[import][cpu][quick]") {
  CpuSolver cpu;
  test::checkTiedPonytail(cpu, 1e-9, 1e-6);
}
