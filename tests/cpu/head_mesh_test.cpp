// A head read from an OBJ (head.mesh): its field's sign and distance against the mesh it came
// from, malformed files refused with their file and line, and the scene taking it up.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "app/preset.h"
#include "sim/groom/hairstyle.h"
#include "sim/head/distance_grid.h"
#include "sim/head/surface_mesh.h"
#include "sim/head/mannequin.h"
#include "sim/head/sphere_fit.h"
#include "sim/head/mesh_field.h"
#include "sim/head/head_model.h"
#include "sim/head/obj_mesh.h"
#include "sim/run/scene_checks.h"
#include "sim/run/simulation.h"
#include "sim/solver/cpu_solver.h"

using namespace csm;
namespace fs = std::filesystem;

namespace {

constexpr double kRadius = 0.1;

// An icosahedron split `levels` times, its vertices on the sphere of kRadius about the origin.
SurfaceMesh icosphere(int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<glm::dvec3> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                               {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                               {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<uint32_t> f = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                             4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                             6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
    auto middle = [&](uint32_t a, uint32_t b) {
      auto [it, added] = mid.try_emplace({std::min(a, b), std::max(a, b)}, uint32_t(p.size()));
      if (added) p.push_back(0.5 * (p[a] + p[b]));
      return it->second;
    };
    std::vector<uint32_t> next;
    for (size_t i = 0; i < f.size(); i += 3) {
      const uint32_t a = f[i], b = f[i + 1], c = f[i + 2];
      const uint32_t ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    f = std::move(next);
  }
  SurfaceMesh m;
  for (const glm::dvec3& q : p) m.positions.emplace_back(kRadius * glm::normalize(q));
  m.indices = f;
  return m;
}

std::string objText(const SurfaceMesh& m) {
  std::ostringstream s;
  s.precision(9);
  s << "# icosphere\no sphere\n";
  for (const glm::vec3& p : m.positions) s << "v " << p.x << " " << p.y << " " << p.z << "\n";
  for (size_t i = 0; i < m.indices.size(); i += 3)
    s << "f " << m.indices[i] + 1 << " " << m.indices[i + 1] + 1 << " " << m.indices[i + 2] + 1
      << "\n";
  return s.str();
}

// A cube of half side 0.05 m as six quads (lines 2-9 the vertices, 10-15 the faces), outward.
std::string cubeText(const std::string& lastFace = "f 2 4 8 6") {
  return "# cube\n"
         "v -0.05 -0.05 -0.05\nv 0.05 -0.05 -0.05\nv -0.05 0.05 -0.05\nv 0.05 0.05 -0.05\n"
         "v -0.05 -0.05 0.05\nv 0.05 -0.05 0.05\nv -0.05 0.05 0.05\nv 0.05 0.05 0.05\n"
         "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\n" +
         lastFace + "\n";
}

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() /
           ("csm_head_mesh_" + std::to_string(reinterpret_cast<uintptr_t>(this)));
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string file = (path / name).string();
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }
};

double meshDistance(const SurfaceMesh& m, const glm::dvec3& p) {
  // Brute force, for the check: the distance to each triangle by its plane and edges.
  double best = 1e300;
  for (size_t i = 0; i < m.indices.size(); i += 3) {
    const glm::dvec3 a(m.positions[m.indices[i]]), b(m.positions[m.indices[i + 1]]),
        c(m.positions[m.indices[i + 2]]);
    const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
    const glm::dvec3 q = p - glm::dot(p - a, n) * n;
    const bool in = glm::dot(glm::cross(b - a, q - a), n) >= 0 &&
                    glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
                    glm::dot(glm::cross(a - c, q - c), n) >= 0;
    if (in) best = std::min(best, std::abs(glm::dot(p - a, n)));
    auto seg = [&](const glm::dvec3& u, const glm::dvec3& v) {
      const double h = std::clamp(glm::dot(p - u, v - u) / glm::dot(v - u, v - u), 0.0, 1.0);
      return glm::length(p - u - h * (v - u));
    };
    best = std::min({best, seg(a, b), seg(b, c), seg(c, a)});
  }
  return best;
}

std::vector<glm::dvec3> spread(const glm::dvec3& lo, const glm::dvec3& hi, int count) {
  std::vector<glm::dvec3> out;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 u(std::fmod(0.5 + i * 0.7548776662, 1.0),
                       std::fmod(0.5 + i * 0.5698402910, 1.0),
                       std::fmod(0.5 + i * 0.4301597090, 1.0));
    out.push_back(lo + u * (hi - lo));
  }
  return out;
}

}  // namespace

TEST_CASE("an OBJ sphere's field: the sign right and the distance the mesh's near the surface",
          "[head_mesh][quick]") {
  TempDir dir;
  const SurfaceMesh sphere = icosphere(3);
  const std::string path = dir.write("sphere.obj", objText(sphere));
  std::string error;
  const std::shared_ptr<const LoadedHead> head = loadHeadMesh(path, &error);
  REQUIRE(head);
  CHECK(error.empty());
  CHECK(openEdges(head->mesh) == 0);
  const DistanceGrid& g = head->grid;
  const double cell = g.cell;
  CHECK(cell == Approx(0.004));
  int near = 0;
  double worst = 0.0;
  for (const glm::dvec3& p : spread(glm::dvec3(-0.14), glm::dvec3(0.14), 4000)) {
    const double d = g.sample(p);
    const double exact = meshDistance(head->mesh, p);
    // Inside the sphere the mesh's inside (the mesh lies within 0.4 mm of the sphere).
    const double r = glm::length(p);
    if (r < kRadius - 0.001) CHECK(d < 0.0);
    if (r > kRadius + 0.001) CHECK(d > 0.0);
    if (exact < 0.012) {
      ++near;
      worst = std::max(worst, std::abs(std::abs(d) - exact));
    }
  }
  CHECK(near > 200);
  INFO("worst distance error near the surface " << worst << " m");
  CHECK(worst < 0.1 * cell);
  // The gradient points outwards, of about unit length.
  glm::dvec3 grad;
  g.sample({0.0, 0.0, 0.102}, &grad);
  CHECK(glm::dot(glm::normalize(grad), glm::dvec3(0, 0, 1)) > 0.99);
  CHECK(glm::length(grad) == Approx(1.0).margin(0.05));
  // The same file again is the same field.
  CHECK(loadHeadMesh(path, nullptr)->grid.nodes == g.nodes);
  // Roots snapped onto it (as a groom file's are) land on the surface.
  const glm::dvec3 snapped = projectToSurface(g, {0.03, 0.09, 0.02});
  CHECK(std::abs(glm::length(snapped) - kRadius) < 0.001);
}

TEST_CASE("an OBJ cube of quads, its faces turned inwards, gives the cube's field",
          "[head_mesh][quick]") {
  TempDir dir;
  // Every face reversed: the reader turns the surface outwards.
  std::string text =
      "v -0.05 -0.05 -0.05\nv 0.05 -0.05 -0.05\nv -0.05 0.05 -0.05\n"
      "v 0.05 0.05 -0.05\nv -0.05 -0.05 0.05\nv 0.05 -0.05 0.05\n"
      "v -0.05 0.05 0.05\nv 0.05 0.05 0.05\n"
      "f 2 4 3 1\nf 7 8 6 5\nf 5 6 2 1\nf 4 8 7 3\nf 3 7 5 1\nf 6 8 4 2\n";
  const std::string path = dir.write("cube.obj", text);
  const std::shared_ptr<const LoadedHead> head = loadHeadMesh(path, nullptr);
  REQUIRE(head);
  CHECK(head->mesh.indices.size() == 36);
  for (const glm::dvec3& p : spread(glm::dvec3(-0.08), glm::dvec3(0.08), 3000)) {
    const glm::dvec3 q = glm::abs(p) - 0.05;
    const double exact = glm::length(glm::max(q, 0.0)) + std::min(std::max({q.x, q.y, q.z}), 0.0);
    if (std::abs(exact) < 0.002) continue;  // the sign at the surface is anyone's
    const double d = head->grid.sample(p);
    CHECK((d < 0.0) == (exact < 0.0));
    // Away from edges and corners a distance to a plane interpolates exactly.
    if (std::abs(exact) < 0.01 && std::max({q.x, q.y, q.z}) > 0.0 &&
        int(q.x > -0.01) + int(q.y > -0.01) + int(q.z > -0.01) == 1)
      CHECK(d == Approx(exact).margin(1e-4));
  }
}

TEST_CASE("malformed OBJ heads are refused with the file and the line", "[head_mesh][quick]") {
  TempDir dir;
  auto refusal = [&](const std::string& name, const std::string& text) {
    const std::string path = dir.write(name, text);
    const io::ObjReadResult r = io::readObjMesh(path);
    CHECK(r.mesh.has_value() == r.error.empty());
    return r.error;
  };
  const std::string cube = cubeText();
  REQUIRE(refusal("good.obj", cube).empty());
  // A face index out of range on line 15 (the file has 8 vertices).
  std::string e = refusal("range.obj", cubeText("f 2 4 9 6"));
  CHECK_THAT(e, Catch::Contains((dir.path / "range.obj").string() + ":15: face vertex index 9 "
                                                                    "is out of range: 8 vertices"));
  e = refusal("negative.obj", cubeText("f 2 4 -9 6"));
  CHECK_THAT(e, Catch::Contains("negative.obj:15: face vertex index -9 is out of range"));
  e = refusal("zero.obj", cubeText("f 0 4 8 6"));
  CHECK_THAT(e, Catch::Contains("zero.obj:15: face vertex index 0"));
  // A non-numeric vertex coordinate on line 4.
  std::string text = cube;
  text.replace(text.find("v 0.05 -0.05 -0.05"), 18, "v 0.05 abc -0.05");
  e = refusal("nan.obj", text);
  CHECK_THAT(e, Catch::Contains("nan.obj:3: vertex coordinate \"abc\" is not a number"));
  text = cube;
  text.replace(text.find("v 0.05 0.05 0.05"), 16, "v 0.05 inf 0.05");
  CHECK_THAT(refusal("inf.obj", text), Catch::Contains("inf.obj:9: vertex coordinate \"inf\" is "
                                                       "not finite"));
  CHECK_THAT(refusal("short.obj", cubeText("f 2 4")),
             Catch::Contains("short.obj:15: a face needs at least 3 vertices"));
  CHECK_THAT(refusal("noint.obj", cubeText("f 2 4 x 6")),
             Catch::Contains("noint.obj:15: face vertex index \"x\" is not an integer"));
  // No faces, no vertices.
  CHECK_THAT(refusal("nofaces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"),
             Catch::Contains("nofaces.obj: no faces"));
  CHECK_THAT(refusal("empty.obj", "# nothing\n"), Catch::Contains("empty.obj: no vertices"));
  // Open: the cube without its last face is capped (head_mesh_quirks below); two faces that
  // share only a corner leave a boundary that is not a loop: refused, at the first face with an
  // open edge (line 10).
  CHECK(refusal("open.obj", cubeText("")).empty());
  CHECK_THAT(refusal("pinched.obj",
                     "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv -0.1 0 0\nv 0 -0.1 0\n"
                     "f 1 2 3\nf 1 4 5\n"),
             Catch::Contains("pinched.obj:6: the surface is not closed: 6 edges"));
  // One face turned against its neighbours is not consistently oriented.
  CHECK_THAT(refusal("flipped.obj", cubeText("f 6 8 4 2")),
             Catch::Contains("flipped.obj:10: the surface is not closed"));
  // Centimetres.
  const std::string big = std::regex_replace(cube, std::regex("0\\.05"), "50");
  // read in the file's units: the scene brings it into the head frame (head_fit_test.cpp), and
  // refuses it once fitted only when it is still over 1 m across.
  CHECK(refusal("cm.obj", big).empty());
  dir.write("cm.obj", big);
  HeadFitOptions metres;
  metres.scale = 1.0f;
  std::string why;
  CHECK_FALSE(loadHeadMesh((dir.path / "cm.obj").string(), &why, metres));
  CHECK_THAT(why, Catch::Contains("cm.obj: the mesh is 100.00 m across once in the head frame"));
  CHECK(loadHeadMesh((dir.path / "cm.obj").string(), &why) != nullptr);
  // Missing.
  const io::ObjReadResult missing = io::readObjMesh((dir.path / "absent.obj").string());
  CHECK_THAT(missing.error, Catch::Contains((dir.path / "absent.obj").string() + ": "));
}

TEST_CASE("head.mesh: the scene collides with and draws the OBJ, relative to the preset",
          "[head_mesh]") {
  TempDir dir;
  dir.write("sphere.obj", objText(icosphere(2)));
  dir.write("bad.obj", cubeText("f 2 4 9 6"));
  Config c;
  c.collision.headShape = HeadShape::Sdf;
  CHECK(HeadModel::require(c)->field() == &mannequinGrid());
  CHECK(HeadModel::require(c)->surface() == &mannequinMesh());
  c.head.mesh = "sphere.obj";
  c.head.meshDir = dir.path.string();
  CHECK(crossCheck(c).empty());
  const std::shared_ptr<const LoadedHead> head =
      loadHeadMesh((dir.path / "sphere.obj").string(), nullptr);
  REQUIRE(head);
  const std::shared_ptr<const HeadModel> model = HeadModel::require(c);
  REQUIRE(model->field());
  CHECK(model->field()->nodes == head->grid.nodes);
  CHECK(model->surface()->indices == head->mesh.indices);
  CHECK_FALSE(model->mannequin());
  // A model built after it for the same file shares its mesh and field (read once a scene).
  CHECK(HeadModel::build(c, nullptr, model.get())->field() == model->field());
  c.collision.headShape = HeadShape::Spheres;
  CHECK(HeadModel::require(c)->field() == nullptr);
  CHECK(HeadModel::require(c)->surface() == nullptr);
  c.collision.headShape = HeadShape::Sdf;

  // Hair grown on it has its roots on the sphere (seen from the mannequin's scalp centre).
  c.hairstyle.strands = 200;
  const Groom g = growHairstyle(c, *HeadModel::require(c));
  REQUIRE(g.strandCount() == 200);
  for (size_t s = 0; s < g.strandCount(); ++s)
    CHECK(std::abs(glm::length(glm::dvec3(g.points[g.first[s]])) - kRadius) < 0.002);

  // Spheres fitted to it: the first is the sphere itself.
  c.collision.headShape = HeadShape::Spheres;
  c.head.fitSpheres = true;
  c.head.spheres = {{{0.0f, 0.5f, 0.0f}, 0.01f}, {{0.0f, 0.6f, 0.0f}, 0.01f}};  // only counted
  const std::vector<Sphere> fitted = HeadModel::require(c)->spheres();
  REQUIRE(fitted.size() == c.head.spheres.size());
  const double cell = head->grid.cell;
  CHECK(glm::length(glm::dvec3(fitted[0].center)) < cell);
  CHECK(std::abs(fitted[0].radius - kRadius) < cell);
  c.head.fitSpheres = false;
  c.head.spheres = HeadConfig{}.spheres;
  c.collision.headShape = HeadShape::Sdf;

  // A bad file is refused where the head is built (once a scene), with its file and line;
  // crossCheck reads no file.
  c.head.mesh = "bad.obj";
  CHECK(crossCheck(c).empty());
  std::string headError;
  CHECK(HeadModel::build(c, &headError) == nullptr);
  CHECK_THAT(headError, Catch::StartsWith("head.mesh: " + (dir.path / "bad.obj").string() +
                                          ":15: face vertex index 9"));

  // A preset names it relative to its own folder.
  dir.write("good.json", R"({"head": {"mesh": "sphere.obj"}, "hairstyle": {"strands": 10}})");
  dir.write("bad.json", R"({"head": {"mesh": "bad.obj"}})");
  Preset p = defaultPreset();
  PresetErrors errors;
  CHECK(loadPreset((dir.path / "good.json").string(), p, errors));
  CHECK(p.scene.head.mesh == "sphere.obj");
  CHECK(HeadModel::require(p.scene)->field()->nodes == head->grid.nodes);
  // Reading a preset reads no head: its file is read where the scene's head is built
  // (setupScene, --validate and a scene's load, which name the preset and the file's line:
  // tests/cli/head_mesh.sh).
  Preset q = defaultPreset();
  CHECK(loadPreset((dir.path / "bad.json").string(), q, errors));
  headError.clear();
  CHECK(HeadModel::build(q.scene, &headError) == nullptr);
  CHECK_THAT(headError,
             Catch::StartsWith("head.mesh: " + (dir.path / "bad.obj").string() + ":15: "));
}

TEST_CASE("head.mesh gone when the scene loads: an error naming the file, not the mannequin",
          "[head_mesh][quick]") {
  TempDir dir;
  dir.write("sphere.obj", objText(icosphere(2)));
  Config c = Config{};
  c.hairstyle.strands = 20;
  c.head.mesh = "sphere.obj";
  c.head.meshDir = dir.path.string();
  REQUIRE(crossCheck(c).empty());
  std::filesystem::remove(dir.path / "sphere.obj");  // checked, then gone before it loads
  std::string error;
  CHECK(HeadModel::build(c, &error) == nullptr);
  CHECK_THAT(error, Catch::Contains((dir.path / "sphere.obj").string()));
  Simulation sim(std::make_unique<CpuSolver>());
  error.clear();
  CHECK_FALSE(sim.load(c, dir.path.string(), &error));
  CHECK_THAT(error, Catch::StartsWith("head.mesh: " + (dir.path / "sphere.obj").string()));
  // A solver builds no head of its own: run with none handed in, it says so rather than
  // colliding with another head.
  CpuSolver solver;
  Groom strand;
  strand.addStrand({glm::vec3(0.0f, 0.20f, 0.0f), glm::vec3(0.0f, 0.19f, 0.0f),
                    glm::vec3(0.0f, 0.18f, 0.0f), glm::vec3(0.0f, 0.17f, 0.0f)});
  solver.reset(strand, c, Pose{});
  CHECK_THAT(solver.failure(), Catch::Contains("no head"));
}

TEST_CASE("head.mesh is read once: a scene loaded with the head built from it reads nothing again",
          "[head_mesh]") {
  TempDir dir;
  dir.write("sphere.obj", objText(icosphere(2)));
  Config c = Config{};
  c.hairstyle.strands = 20;
  c.head.mesh = "sphere.obj";
  c.head.meshDir = dir.path.string();
  const std::shared_ptr<const HeadModel> built = HeadModel::require(c);  // setupScene's
  std::filesystem::remove(dir.path / "sphere.obj");
  // The checks of an edit read no file.
  CHECK(crossCheck(c).empty());
  // The scene loaded with the head handed in uses its mesh and field: the file, gone now, is
  // not read again.
  Simulation sim(std::make_unique<CpuSolver>());
  std::string error;
  REQUIRE(sim.load(c, dir.path.string(), &error, built));
  CHECK(sim.head().field() == built->field());
  // Without it, or with a head of another file (the mannequin's), the scene reads the file,
  // and finds it gone.
  Simulation fresh(std::make_unique<CpuSolver>());
  CHECK_FALSE(fresh.load(c, dir.path.string(), &error));
  CHECK_THAT(error, Catch::Contains((dir.path / "sphere.obj").string()));
  Config mannequin = Config{};
  Simulation other(std::make_unique<CpuSolver>());
  CHECK_FALSE(other.load(c, dir.path.string(), &error, HeadModel::require(mannequin)));
}

// Found by fuzz_obj (tests/fuzz/regressions/obj/): a NUL byte ended tinyobjloader's line
// where our checks read on; a face with no area (three vertices on a line) gave the field's
// nodes on it the face's normal, NaN.
TEST_CASE("OBJ heads: NUL bytes are refused, and faces with no area keep the field finite",
          "[head_mesh][quick]") {
  std::string text = cubeText();
  text.insert(text.find("v 0.05 -0.05 -0.05") + 9, std::string("\0\0 7", 4));
  const io::ObjReadResult nul = io::parseObjMesh(text, "nul.obj");
  CHECK_FALSE(nul.mesh);
  CHECK_THAT(nul.error, Catch::Contains("nul.obj:3: a NUL byte; an OBJ file is text"));

  // Vertices 1, 3 and 7 lie on the line x = y = z, and so do nodes of the field's grid.
  const std::string sliver =
      "v -0.1 -0.1 -0.1\nv -0.1 -0.1 0.1\nv 0 0 0\nv 0.1 -0.1 -0.1\nv 0.1 -0.1 0.05\n"
      "v 0.1 0.1 -0.1\nv 0.1 0.1 0.1\n"
      "f 1 2 3\nf 4 6 7\nf 4 7 5\nf 1 4 5\nf 1 5 2\nf 1 3 7\nf 1 7 6\nf 1 6 4\nf 2 5 7\n"
      "f 2 7 3\n";
  const io::ObjReadResult r = io::parseObjMesh(sliver, "sliver.obj");
  REQUIRE(r.mesh);
  // fuzz_obj's cell (a tenth of the box with its margins) put nodes on that line.
  for (double cell : {0.004, (double(0.1f) - double(-0.1f) + 0.04) / 9.0}) {
    const DistanceGrid g = meshDistanceGrid(*r.mesh, cell, 0.02);
    size_t bad = 0;
    for (const glm::vec4& n : g.nodes) bad += !std::isfinite(n.x + n.y + n.z + n.w);
    CHECK(bad == 0);
  }
}

// Found by fuzz_obj (tests/fuzz/regressions/obj/carriage_return_after_v.obj): tinyobjloader
// ends a line at a lone "\r" too, so "v\r 0.1 0.1 0.1" is no vertex to it; our checks counted
// one, passed a face that used it, and the faces were indexed past the vertices read. Now our
// lines are its lines, and a "v" with no coordinates is refused.
TEST_CASE("OBJ heads: lines end where tinyobjloader ends them (LF, CR LF, a lone CR)",
          "[head_mesh][quick]") {
  const std::string text = cubeText();
  std::string split = text;
  split.replace(split.find("v 0.05 -0.05 -0.05"), 2, "v\r");
  const io::ObjReadResult r = io::parseObjMesh(split, "split.obj");
  CHECK_FALSE(r.mesh);
  CHECK_THAT(r.error, Catch::Contains("split.obj:3: vertex has 0 coordinates, expected 3"));

  // The same cube with Windows and classic Mac line ends reads as with "\n".
  const io::ObjReadResult plain = io::parseObjMesh(text, "cube.obj");
  REQUIRE(plain.mesh);
  for (const std::string end : {"\r\n", "\r"}) {
    std::string other;
    for (char c : text) other += c == '\n' ? end : std::string(1, c);
    const io::ObjReadResult r2 = io::parseObjMesh(other, "cube.obj");
    INFO("line end " << (end == "\r" ? "\\r" : "\\r\\n") << ": " << r2.error);
    REQUIRE(r2.mesh);
    CHECK(r2.mesh->positions == plain.mesh->positions);
    CHECK(r2.mesh->indices == plain.mesh->indices);
  }
}

namespace {

// The sphere without the faces below y = -0.07 m: a hole like a scan's neck.
SurfaceMesh openSphere() {
  SurfaceMesh m = icosphere(3);
  std::vector<uint32_t> kept;
  for (size_t i = 0; i < m.indices.size(); i += 3) {
    const float y = std::min({m.positions[m.indices[i]].y, m.positions[m.indices[i + 1]].y,
                              m.positions[m.indices[i + 2]].y});
    if (y > -0.07f) kept.insert(kept.end(), {m.indices[i], m.indices[i + 1], m.indices[i + 2]});
  }
  m.indices = kept;
  return m;
}

// Inside the open sphere's cap (y > -0.06, well inside) the field is negative; outside the
// sphere, positive; through the hole (below the cap's plane, inside the sphere's radius) the cap
// closes it: nothing below y = -0.075 is inside.
void checkCapped(const LoadedHead& head) {
  for (const glm::dvec3& p : spread(glm::dvec3(-0.13), glm::dvec3(0.13), 3000)) {
    const double r = glm::length(p);
    const double d = head.grid.sample(p);
    if (r < 0.09 && p.y > -0.055) CHECK(d < 0.0);
    if (r > 0.11) CHECK(d > 0.0);
    if (p.y < -0.08) CHECK(d > 0.0);
  }
}

std::string plyHeader(const SurfaceMesh& m, const std::string& format) {
  return "ply\r\nformat " + format + " 1.0\r\ncomment a scan, open at the neck\r\n" +
         "element vertex " + std::to_string(m.positions.size()) +
         "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\n"
         "property float ny\nproperty float nz\nproperty uchar red\n" +
         "element face " + std::to_string(m.indices.size() / 3) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

}  // namespace

TEST_CASE(
    "OBJ and PLY heads as the tools write them: CRLF, NUL padding, materials, quads, "
    "n-gons, negative indices, binary and ASCII PLY, a hole capped",
    "[head_mesh][quick]") {
  TempDir dir;
  // ZBrush's kind of OBJ: CRLF header lines, materials, groups, texture coordinates and normals,
  // quads and an n-gon, negative indices, a NUL byte as the last line.
  const std::string zbrush =
      "#ZBrush OBJ Export\r\nmtllib head.mtl\r\nusemtl skin\r\ng cube\r\ns 1\r\n"
      "v -0.05 -0.05 -0.05\r\nv 0.05 -0.05 -0.05\r\nv -0.05 0.05 -0.05\r\nv 0.05 0.05 -0.05\n"
      "v -0.05 -0.05 0.05\nv 0.05 -0.05 0.05\nv -0.05 0.05 0.05\nv 0.05 0.05 0.05\n"
      "v 0 0.05 -0.05\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\no cube\n"
      "f 1/1/1 3/2/1 9/3/1 4/4/1 2/1/1\nf 5/1 6/2 8/3 7/4\nf 1//1 2//1 6//1 5//1\n"
      "f -1 3 7 8 4\nf 1 5 7 3\nf -8 -6 -2 -4\n" +
      std::string("\0", 1);
  const std::string path = dir.write("zbrush.obj", zbrush);
  const io::ObjReadResult z = io::readHeadMeshFile(path);
  INFO(z.error);
  REQUIRE(z.mesh);
  CHECK(z.cappedHoles == 0);
  // The cube's eight and the vertex two pentagons share on an edge.
  CHECK(z.mesh->positions.size() == 9);
  // A NUL byte before the last line is still refused.
  std::string inner = zbrush;
  inner.insert(inner.find("vt 0 0"), std::string("\0\n", 2));
  CHECK_THAT(io::parseObjMesh(inner, "inner.obj").error, Catch::Contains("a NUL byte"));

  // A sphere open at the neck, as OBJ and as PLY (binary both ends, ASCII): capped alike.
  const SurfaceMesh open = openSphere();
  REQUIRE(openEdges(open) > 0);
  std::string ascii = plyHeader(open, "ascii");
  for (const glm::vec3& p : open.positions)
    ascii += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) +
             " 0 1 0 200\n";
  for (size_t i = 0; i < open.indices.size(); i += 3)
    ascii += "3 " + std::to_string(open.indices[i]) + " " + std::to_string(open.indices[i + 1]) +
             " " + std::to_string(open.indices[i + 2]) + "\n";
  auto binary = [&](bool big) {
    std::string b = plyHeader(open, big ? "binary_big_endian" : "binary_little_endian");
    auto put = [&](const void* v, size_t n) {
      const char* c = static_cast<const char*>(v);
      for (size_t k = 0; k < n; ++k) b += c[big ? n - 1 - k : k];
    };
    for (const glm::vec3& p : open.positions) {
      const float row[6] = {p.x, p.y, p.z, 0.0f, 1.0f, 0.0f};
      for (const float f : row) put(&f, 4);
      b += char(200);
    }
    for (size_t i = 0; i < open.indices.size(); i += 3) {
      b += char(3);
      for (int k = 0; k < 3; ++k) {
        const int32_t v = int32_t(open.indices[i + k]);
        put(&v, 4);
      }
    }
    return b;
  };
  const std::vector<std::pair<std::string, std::string>> files = {{"open.obj", objText(open)},
                                                                  {"open_ascii.ply", ascii},
                                                                  {"open_le.ply", binary(false)},
                                                                  {"open_be.ply", binary(true)}};
  for (const auto& [name, text] : files) {
    INFO(name);
    const std::string file = dir.write(name, text);
    const io::ObjReadResult r = io::readHeadMeshFile(file);
    INFO(r.error);
    REQUIRE(r.mesh);
    CHECK(r.cappedHoles == 1);
    CHECK(openEdges(*r.mesh) == 0);
    const std::shared_ptr<const LoadedHead> head = loadHeadMesh(file, nullptr);
    REQUIRE(head);
    checkCapped(*head);
  }
  // A PLY face out of range, with its face and byte.
  std::string bad = ascii.substr(0, ascii.rfind('\n', ascii.size() - 2) + 1) + "3 99999 0 1\n";
  const io::ObjReadResult r = io::readHeadMeshFile(dir.write("bad.ply", bad));
  CHECK_THAT(r.error, Catch::Contains(": face " + std::to_string(open.indices.size() / 3 - 1)) &&
                          Catch::Contains("vertex index 99999 is out of range"));
}
