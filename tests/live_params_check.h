// Every parameter marked Effect::Live changes the motion when it is changed on a running
// simulation (Simulation::setConfig after a few frames, no reset), on whichever solver
// `make` gives. Shared by the CPU and GPU tiers.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "sim/param/sim_params.h"
#include "sim/run/simulation.h"
#include "sim/verify/scenes.h"
#include "tests/param_variants.h"

namespace csm::test {

// A small scene with every live feature in play: the head nods, wind with gusts and
// turbulence, hair-hair contacts and volume, strain limiting, calibrated stiffness asking for more
// steps than the fewest (so the cap on steps can bind). `paper`: the paper's stiffness model.
inline Config liveScene(bool paper = false) {
  Config c = smallSceneConfig({.strands = 40,
                               .minParticles = 6,
                               .maxParticles = 12,
                               .lengthMin = 0.15f,
                               .lengthMax = 0.25f});
  c.head.motion = HeadMotion::Nod;
  c.head.amplitude = 20.0f;
  c.head.frequency = 1.0f;
  c.wind.strength = 4.0f;
  c.wind.gusts = 0.5f;
  c.wind.gustFrequency = 1.0f;
  c.wind.turbulence = 0.5f;
  c.collision.mode = CollisionMode::VolumeStrands;  // both kinds of hair-hair
  c.collision.volumeFraction = 0.02f;               // pushes
  c.sim.substeps = 1;
  if (paper) {
    c.sim.stiffnessModel = StiffnessModel::Paper;
    c.sim.substeps = 4;
  }
  return c;
}

// A clip of five frames (0.13 s) whose body walks 5 cm a frame along +z: past its end within a
// live check's frames, so that looping and travel show.
inline Config clipScene() {
  // Each process its own file: the CPU and GPU binaries run this at once.
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("csm_live_check_" + std::to_string(::getpid()) + ".bvh"))
                               .string();
  std::ofstream out(path);
  out << "HIERARCHY\nROOT Hips\n{\n OFFSET 0 95 0\n CHANNELS 6 Xposition Yposition Zposition "
         "Zrotation Xrotation Yrotation\n JOINT Head\n {\n  OFFSET 0 60 0\n  CHANNELS 3 "
         "Zrotation Xrotation Yrotation\n  End Site\n  {\n   OFFSET 0 15 0\n  }\n }\n}\n"
         "MOTION\nFrames: 5\nFrame Time: 0.0333333\n";
  for (int f = 0; f < 5; ++f) out << "0 95 " << 5 * f << " 0 " << 4 * f << " 0 0 0 0\n";
  Config c = liveScene();
  c.motion.clip = path;
  c.motion.scale = 0.01f;
  c.motion.up = ClipUp::Y;
  c.motion.facing = ClipFacing::PlusZ;
  return c;
}

struct LiveCheck {
  std::vector<std::string> tested;    // keys
  std::vector<std::string> noEffect;  // keys none of whose values changed the motion
};

// Runs `before` frames on `base`, then `after` frames on `changed` (given live).
inline std::vector<glm::vec4> runLive(Simulation& sim, const Config& base, const Config& changed,
                                      int before = 4, int after = 4) {
  std::string error;
  INFO(error);
  REQUIRE(sim.load(base, "", &error));
  for (int f = 0; f < before; ++f) sim.stepFrame();
  REQUIRE(sim.setConfig(changed, &error));
  for (int f = 0; f < after; ++f) sim.stepFrame();
  std::vector<glm::vec4> x;
  sim.readPositions(x);
  return x;
}

inline bool samePositions(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (!(a[i] == b[i])) return false;  // NaN differs from everything
  return true;
}

inline LiveCheck checkLiveParams(std::unique_ptr<Solver> solver) {
  Simulation sim(std::move(solver));
  // Each parameter on the first scene it applies to (the stiffness models' own parameters,
  // the penalty model's, the guides' strand contacts).
  Config penalty = liveScene();
  penalty.collision.model = ContactModel::Penalty;
  Config guided = liveScene();
  guided.hairstyle.guides = 10;  // of 40
  const std::vector<Config> bases = {liveScene(), liveScene(true), penalty, guided, clipScene()};
  std::vector<std::vector<glm::vec4>> references;
  for (const Config& base : bases) {
    references.push_back(runLive(sim, base, base));
    // The comparison means something only if the same run gives the same positions.
    REQUIRE(samePositions(runLive(sim, base, base), references.back()));
  }
  LiveCheck check;
  for (const Param<Config>& p : simParams()) {
    if (p.effect != Effect::Live) continue;
    check.tested.emplace_back(p.key);
    size_t b = 0;
    while (b + 1 < bases.size() && !p.applies(bases[b])) ++b;
    bool changed = false;
    for (const Config& variant : paramVariants(p, bases[b])) {
      if (!samePositions(runLive(sim, bases[b], variant), references[b])) {
        changed = true;
        break;
      }
    }
    if (!changed) check.noEffect.emplace_back(p.key);
  }
  return check;
}

}  // namespace csm::test
