// An imported groom with the flaws of real ones (the TressFX 4 groom of issue 38: strands of a
// few micrometres, segments under a micrometre, strands shorter than a segment), held to the
// same promises on the CPU reference (tests/cpu/groom_import_test.cpp) and the GPU solver
// (tests/gpu/gpu_import_test.cpp): it runs at the steps its normal strands need, and after 30
// frames no segment is stretched past the strain limit and no particle is inside the head.
#pragma once

#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/groom/hairstyle.h"
#include "sim/groom/scene_groom.h"
#include "sim/core/pose.h"
#include "sim/core/solver.h"
#include "sim/head/head_model.h"
#include "sim/verify/solver_head.h"

namespace csm::test {

// A file's placement: centimetres, 1.5 m up, as a DCC scene has it.
inline glm::vec3 toFile(const glm::vec3& metres) {
  return 100.0f * metres + glm::vec3(3.0f, 150.0f, -2.0f);
}

// The scene's own hairstyle written out as a file would have it, every strand with four points
// 1 um apart after its root and before its tip; with `degenerate`, three more strands: 32 points
// over 7.5 um, one point repeated, and a 1.5 cm strand of two points (long enough to keep,
// stiffer than the rest by its length alone).
inline Groom importedGroom(const Config& c, bool degenerate) {
  const Groom grown = growHairstyle(c, *HeadModel::require(c));
  Groom file;
  const glm::vec3 um(0.0f, 1e-4f, 0.0f);  // 1 um, in cm
  for (size_t s = 0; s < grown.strandCount(); ++s) {
    std::vector<glm::vec3> pts;
    const uint32_t a = grown.first[s], b = grown.first[s + 1];
    for (uint32_t i = a; i < b; ++i) {
      const glm::vec3 p = toFile(grown.points[i]);
      if (i + 1 == b)
        for (int k = 3; k >= 1; --k) pts.push_back(p - float(k) * um);
      pts.push_back(p);
      if (i == a)
        for (int k = 1; k <= 3; ++k) pts.push_back(p + float(k) * um);
    }
    file.addStrand(pts);
  }
  if (degenerate) {
    const glm::vec3 root = toFile(grown.points[grown.first[1]]);
    std::vector<glm::vec3> tiny;
    for (int i = 0; i < 32; ++i) tiny.push_back(root + glm::vec3(7.5e-4f * float(i) / 31.0f, 0, 0));
    file.addStrand(tiny);
    file.addStrand({root, root, root});
    file.addStrand({root, root + glm::vec3(0.0f, -1.5f, 0.0f)});
  }
  return file;
}

// The groom as a scene imports it.
inline Groom importFor(const Config& c, const Groom& file, GroomReport* report = nullptr) {
  Config scene = c;
  scene.hairstyle.strands = 1000000;  // every strand of the file
  Groom out;
  std::string error;
  const bool ok =
      fitFileGroom(scene, *HeadModel::require(scene), file, "imported.hair", out, &error, report);
  INFO(error);
  REQUIRE(ok);
  return out;
}

// 30 frames of the flawed import: strain within the limit (float positions: 1e-4 more), no
// particle in the head, no NaN.
inline void checkImportedRun(Solver& solver, double floatSlack) {
  Config c;
  c.hairstyle.strands = 150;
  c.collision.mode = CollisionMode::Head;
  c.collision.headShape = HeadShape::Sdf;
  c.wind.strength = 3.0f;
  c.head.motion = HeadMotion::Nod;
  GroomReport report;
  const Groom g = importFor(c, importedGroom(c, true), &report);
  CHECK(report.repair.droppedStrands >= 2);
  CHECK(report.repair.mergedPoints >= 6 * 150);
  resetWithHead(solver, g, c, headPose(c.head, 0.0));
  double t = 0.0;
  FrameSample last;
  for (int f = 0; f < 30; ++f, t += c.sim.dt) {
    solver.stepFrame(headPose(c.head, t), headPose(c.head, t + c.sim.dt));
    solver.requestSample(f);
    while (auto s = solver.takeSample(f == 29)) last = *s;
  }
  const Accuracy& a = last.accuracy;
  INFO(solver.name() << ": max strain " << a.maxStrain << ", inside the head " << a.headPenetrations
                     << ", NaN " << a.nanCount);
  CHECK(last.frame == 29);
  CHECK(a.nanCount == 0);
  CHECK(a.maxStrain <= double(c.sim.strainLimit) + floatSlack);
  CHECK(a.headPenetrations == 0);
}

}  // namespace csm::test
