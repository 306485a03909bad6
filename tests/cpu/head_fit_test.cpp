// A head mesh brought into the head frame (sim/head/head_fit.h): the mannequin's own head, written
// out in other units and axes as scanners and tools write heads, comes back where it was.
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "sim/head/head_fit.h"
#include "sim/head/mannequin.h"
#include "sim/head/surface_mesh.h"

using namespace csm;

namespace {

// The mannequin's head moved out of the head frame: p -> rotation * p * unitsPerMetre + offset.
SurfaceMesh moved(const glm::dmat3& rotation, double unitsPerMetre, const glm::dvec3& offset) {
  SurfaceMesh m = mannequinHeadMesh();
  for (glm::vec3& p : m.positions) p = glm::vec3(rotation * glm::dvec3(p) * unitsPerMetre + offset);
  for (glm::vec3& n : m.normals) n = glm::vec3(rotation * glm::dvec3(n));
  return m;
}

// The largest distance between a fitted mesh's vertices and the mannequin's.
double farthest(const SurfaceMesh& m) {
  const SurfaceMesh& ref = mannequinHeadMesh();
  double far = 0.0;
  for (size_t v = 0; v < m.positions.size(); ++v)
    far = std::max(far, double(glm::length(m.positions[v] - ref.positions[v])));
  return far;
}

// z up with the face toward -y (Blender's axes): the head frame's y to the file's +z, its z to -y.
const glm::dmat3 kZUpFaceMinusY(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0));
// y up, the face toward +x.
const glm::dmat3 kFacePlusX(glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0));

}  // namespace

TEST_CASE("the mannequin's cranium is where the head fit puts every head's", "[head_fit][quick]") {
  const Cap cap = craniumCap(mannequinHeadMesh(), glm::dvec3(0, 1, 0), 0.07);
  INFO("centre " << cap.centre.x << " " << cap.centre.y << " " << cap.centre.z << " radius "
                 << cap.radius);
  CHECK(std::abs(cap.centre.x) < 1e-3);
  CHECK(std::abs(cap.centre.y - kMannequinCraniumY) < 2e-3);
  CHECK(std::abs(cap.centre.z - kMannequinCraniumZ) < 2e-3);
  CHECK(std::abs(cap.radius - kMannequinCraniumRadius) < 2e-3);
  // Already in the head frame: nothing is done, and it says so.
  SurfaceMesh m = mannequinHeadMesh();
  const HeadFit fit = fitHead(m, {}, {});
  INFO(fit.text());
  CHECK_FALSE(fit.changed());
  CHECK(fit.unit == "m");
  CHECK(fit.facing == "+z");
  CHECK_THAT(fit.facingWhy, Catch::Contains("the face's detail"));
}

TEST_CASE("a head in centimetres, millimetres or inches is found in its unit and placed",
          "[head_fit][quick]") {
  struct Case {
    double perMetre;
    const char* unit;
  };
  for (const Case& u : {Case{100.0, "cm"}, Case{1000.0, "mm"}, Case{1.0 / 0.0254, "in"}}) {
    SurfaceMesh m = moved(glm::dmat3(1.0), u.perMetre, glm::dvec3(3.0, 150.0, -7.0));
    const HeadFit fit = fitHead(m, {}, {});
    INFO(u.unit << ": " << fit.text());
    CHECK(fit.unit == u.unit);
    CHECK(std::abs(fit.scale * u.perMetre - 1.0) < 1e-9);
    CHECK(farthest(m) < 3e-3);
  }
}

TEST_CASE("a head with z up facing -y, or facing +x, is turned into the head frame",
          "[head_fit][quick]") {
  SECTION("z up, the face toward -y, open at the neck: up from the opening, facing from the face") {
    SurfaceMesh m = moved(kZUpFaceMinusY, 1.0, glm::dvec3(0.1, -0.2, 1.6));
    // The neck's opening, where the reader capped it: below the head along the file's -z.
    const glm::vec3 neck =
        glm::vec3(kZUpFaceMinusY * glm::dvec3(0, -0.2, 0) + glm::dvec3(0.1, -0.2, 1.6));
    const HeadFit fit = fitHead(m, {neck}, {});
    INFO(fit.text());
    CHECK(fit.up == "+z");
    CHECK(fit.facing == "-y");
    CHECK_THAT(fit.upWhy, Catch::Contains("opening at the neck"));
    CHECK(farthest(m) < 3e-3);
  }
  SECTION("y up, the face toward +x: the face's detail names it") {
    SurfaceMesh m = moved(kFacePlusX, 1.0, glm::dvec3(0.0));
    const HeadFit fit = fitHead(m, {}, {});
    INFO(fit.text());
    CHECK(fit.facing == "+x");
    CHECK(farthest(m) < 3e-3);
  }
  SECTION("the preset's axes and scale override what is inferred") {
    SurfaceMesh m = moved(glm::dmat3(1.0), 1.0, glm::dvec3(0.0));
    HeadFitOptions o;
    o.facing = ClipFacing::MinusZ;
    o.scale = 2.0f;
    const HeadFit fit = fitHead(m, {}, o);
    INFO(fit.text());
    CHECK(fit.facing == "-z");
    CHECK(fit.unit.empty());
    CHECK(fit.scale == 2.0);
    CHECK_THAT(fit.text(), Catch::Contains("head.mesh_facing"));
  }
}
