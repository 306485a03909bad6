// The torture map's far ends (sim/verify/torture.h, docs/RELIABILITY.md "Torture map"), held to the
// same criteria on the CPU reference (tests/cpu/torture_test.cpp) and the GPU solver
// (tests/gpu/gpu_torture_test.cpp). Each axis is one test case; a failing cell is named, with
// its numbers, in the message. The full map is `csmhair-bench --only torture [--gpu]`.
#pragma once

#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "app/preset.h"
#include "sim/verify/torture.h"

namespace csm::test {

// The default preset with its first 60 strands, 1 s a cell (the map runs 150 for 2 s).
inline constexpr int kTortureStrands = 60;
inline constexpr double kTortureSeconds = 1.0;

inline Config tortureBase() {
  Config c = defaultPreset().scene;
  c.hairstyle.strands = kTortureStrands;
  return c;
}

inline std::vector<TortureCell> tortureCorners(const std::string& axis) {
  std::vector<TortureCell> out;
  for (TortureCell& c : tortureCells(tortureBase(), TortureScope::Corners, kTortureSeconds))
    if (c.axis == axis) out.push_back(std::move(c));
  return out;
}

// Every cell of the axis in every collision mode, each criterion checked on its own so that
// one run reports every cell and criterion that fails.
inline void checkTortureAxis(const SolverMaker& make, const std::string& solver,
                             const std::string& axis) {
  const std::vector<TortureCell> cells = tortureCorners(axis);
  REQUIRE(!cells.empty());
  const TortureCriteria criteria;
  for (const TortureCell& cell : cells) {
    const TortureResult r = runTorture(make, cell, criteria);
    INFO(solver << ", " << cell.name() << ": " << r.frames << " frames; "
                << (r.pass() ? "passes" : r.failures()));
    CHECK(r.frames == std::lround(cell.duration / cell.config.sim.dt));
    CHECK(r.finite);
    CHECK(r.maxStrain <= r.strainLimit + criteria.strainTolerance);
    if (r.headChecked) CHECK(r.deepestMm <= criteria.penetrationMm);
    CHECK(r.peakSpeed <= r.speedBound);
  }
}

}  // namespace csm::test
