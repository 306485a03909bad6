// What the groom targets do with a groom their reader accepted: the reader's promise (a sound
// structure, finite points), then the steps a preset naming the file takes
// (sim/groom/scene_groom.h's fitFileGroom: strands kept, the fit to the head, roots snapped,
// resampling), on the spheres or on the mannequin's field as `selector` says, and their promise:
// a groom the solver can run.
#pragma once

#include <cmath>
#include <string>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/groom/scene_groom.h"
#include "sim/groom/read_common.h"
#include "sim/head/head_model.h"
#include "tests/fuzz/fuzz_common.h"

namespace csm::fuzz {

inline void checkFinite(const Groom& g, const std::string& where) {
  for (const glm::vec3& p : g.points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail(where + ": a point is not finite");
  for (size_t s = 0; s < g.strandCount(); ++s) {
    bool moves = false;
    for (uint32_t i = g.first[s] + 1; i < g.first[s + 1]; ++i)
      moves = moves || g.points[i] != g.points[g.first[s]];
    if (!moves) fail(where + ": a strand has zero length");
  }
  for (float t : g.thickness)
    if (!std::isfinite(t)) fail(where + ": a thickness is not finite");
}

inline void fitAsPreset(const Groom& read, const std::string& name, unsigned selector,
                        bool findRoots = false) {
  if (std::string problem = io::checkGroomStructure(read); !problem.empty())
    fail("the reader accepted a broken groom: " + problem);
  checkFinite(read, "the reader accepted a groom");

  Config c;
  // The harness's cap, not the product's: a few strands keep one execution fast (the
  // strands kept are spread over the file, so every strand can still be picked).
  c.hairstyle.strands = 16;
  c.collision.headShape = (selector & 1) ? HeadShape::Sdf : HeadShape::Spheres;
  c.hairstyle.importScale = (selector & 2) ? 0.0f : 1.0f;
  c.hairstyle.resampleTolerance = (selector & 4) ? 0.0f : 0.002f;
  Groom out;
  std::string error;
  GroomReport report;
  if (!fitFileGroom(c, *HeadModel::require(c), read, name, out, &error, &report, findRoots)) {
    if (error.empty()) fail("fitFileGroom failed without a message");
    return;
  }
  if (std::string problem = io::checkGroomStructure(out); !problem.empty())
    fail("fitFileGroom returned a broken groom: " + problem);
  checkFinite(out, "fitFileGroom returned a groom");
  if (report.turnedStrands > read.strandCount()) fail("more strands turned than read");
}

}  // namespace csm::fuzz
