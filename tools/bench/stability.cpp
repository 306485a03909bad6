// Stability maps: each method over time step x its own stiffness knob, on four cantilever
// strands released under gravity (no head, no wind, nothing driving): a blow-up is a
// non-finite state, a segment stretched beyond 100%, or the energy growing past 1.5 x its
// start (sim/verify/measure.h, checkStability).
#include <cmath>
#include <cstdio>
#include <mutex>

#include "tools/bench/bench.h"
#include "tools/bench/csv.h"

namespace csm::bench {
namespace {

struct Axis {
  std::string family;
  std::string stiffnessName;
  std::vector<double> values;
  std::function<Setting(double)> setting;  // substeps are set by the map
};

// The maps' scene: four strands of 16 particles and `length` held out horizontally and released
// (no head, wind or collisions), run with setting `s` for `duration`; blown up past 1.5x the
// energy. The solver's stiffness as it ran.
struct Released {
  StabilityResult result;
  StiffnessInfo stiffness;
};
Released releaseStrands(const Setting& s, double length, double duration) {
  Scene scene = cantileverScene(16, length, 4);
  const int pinned = scene.config.sim.pinned;
  s.apply(scene.config);
  scene.config.sim.pinned = pinned;
  scene.config.collision.mode = CollisionMode::Off;
  Released r;
  r.result = checkStability(s.maker(), scene, duration, 1.0, 1.5);
  r.stiffness = r.result.stiffness;
  return r;
}

}  // namespace

void runStability(const Options& o) {
  const std::vector<int> substeps =
      o.quick ? std::vector<int>{1, 4, 16, 64} : std::vector<int>{1, 2, 4, 8, 16, 32, 64, 128};
  const std::vector<double> ea =
      o.quick ? std::vector<double>{0.001, 0.01, 0.1, 1.0}
              : std::vector<double>{0.001, 0.003, 0.01, 0.03, 0.1, 0.3, 1.0, 3.0};
  const std::vector<double> windows =
      o.quick ? std::vector<double>{1, 2, 4, 8} : std::vector<double>{1, 2, 3, 4, 6, 8, 12, 15};
  auto csm = [](bool limit, float dftl) {
    return [=](double w) {
      Setting s;
      s.solver = "csm";
      s.window = int(w);
      s.strainLimiting = limit;
      s.dftl = dftl;
      return s;
    };
  };
  const std::vector<double> bending =
      o.quick ? std::vector<double>{1e-4, 1e-3, 1e-2, 1e-1}
              : std::vector<double>{1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1, 1.0};
  auto calibrated = [](float dftl) {
    return [=](double b) {
      Setting s;
      s.solver = "csm";
      s.model = StiffnessModel::Calibrated;
      s.bendingStiffness = float(b);
      s.dftl = dftl;
      return s;
    };
  };
  auto springs = [](const char* name) {
    return [=](double k) {
      Setting s;
      s.solver = name;
      s.params.stretchStiffness = k;
      s.params.bendStiffness = 0.2 * k;
      return s;
    };
  };
  std::vector<Axis> axes = {
      {"CSM", "stiffness window w", windows, csm(true, 0.0f)},
      {"CSM, no strain limit", "stiffness window w", windows, csm(false, 0.0f)},
      {"CSM + DFTL 0.9", "stiffness window w", windows, csm(true, 0.9f)},
      // Calibrated: the steps per frame capped at the map's, so that each column is one h;
      // alpha = min(1, k h^2) then saturates at 1 where the stiffness asks for more.
      {"CSM calibrated (steps capped)", "bending stiffness B (m^4/s^2), 4 cm window", bending,
       calibrated(0.0f)},
      {"CSM calibrated + DFTL 0.9 (steps capped)", "bending stiffness B (m^4/s^2), 4 cm window",
       bending, calibrated(0.9f)},
      {"MS explicit", "stretch stiffness EA (N), bending 0.2 EA", ea, springs("ms-explicit")},
      {"MS implicit", "stretch stiffness EA (N), bending 0.2 EA", ea, springs("ms-implicit")},
      {"PBD", "iterations per step (k = 1, bending 0.5)",
       o.quick ? std::vector<double>{1, 4, 16, 64}
               : std::vector<double>{1, 2, 4, 8, 16, 32, 64, 128},
       [](double it) {
         Setting s;
         s.solver = "pbd";
         s.params.iterations = int(it);
         return s;
       }},
      {"FTL (DFTL 0.9)", "bending constraint stiffness per 1/60 s",
       o.quick ? std::vector<double>{0.0, 0.1, 0.5, 1.0}
               : std::vector<double>{0.0, 0.02, 0.05, 0.1, 0.2, 0.5, 0.8, 1.0},
       [](double k) {
         Setting s;
         s.solver = "ftl";
         s.params.ftlBend = k;
         return s;
       }},
  };
  struct Cell {
    int axis;
    double stiffness;
    int substeps;
    StabilityResult result;
  };
  std::vector<Cell> cells;
  for (int a = 0; a < int(axes.size()); ++a)
    for (double k : axes[a].values)
      for (int s : substeps) cells.push_back({a, k, s, {}});
  const double duration = o.quick ? 1.0 : 2.0;
  std::fprintf(stderr, "stability: %zu runs of %.0f s\n", cells.size(), duration);
  parallelFor(int(cells.size()), o.threads, [&](int i) {
    Cell& c = cells[i];
    Setting s = axes[c.axis].setting(c.stiffness);
    s.substeps = c.substeps;
    s.maxSubsteps = c.substeps;
    c.result = releaseStrands(s, 0.25, duration).result;
  });
  Csv csv({"family", "stiffness_name", "stiffness", "substeps", "h", "blowup", "max_strain",
           "energy_ratio", "time"});
  for (const Cell& c : cells) {
    const double h = (1.0 / 60.0) / c.substeps;
    csv.add(axes[c.axis].family).add(axes[c.axis].stiffnessName).add(c.stiffness);
    csv.add(c.substeps).add(h).add(blowupName(c.result.blowup));
    csv.add(c.result.maxStrain).add(c.result.energyRatio).add(c.result.time);
    csv.endRow();
  }
  csv.write(o.out + "/stability.csv");
  int blown = 0;
  for (const Cell& c : cells) blown += c.result.blowup != Blowup::None;
  std::fprintf(stderr, "  %d of %zu runs blew up\n", blown, cells.size());
}

// Soft hair: the calibrated model at small bending numbers B / (g L^3) over the steps a frame and
// the DFTL correction, on the stability map's scene (steps capped at the column's), at 25 cm and
// at 12.5 and 6 cm with B scaled by the length cubed (the same numbers). Energy past 1.5x its
// start is the whip of the strain-limiting sweep, which the goals of soft hair barely oppose
// (softHairDftl in sim/solver/stiffness.h is this map).
void runSoftHair(const Options& o) {
  // B at 25 cm; the window scales with the length.
  const std::vector<double> bending = {1e-4, 2e-4, 3e-4, 5e-4, 1e-3, 2e-3};
  const std::vector<int> substeps = {1, 2, 4, 8, 16, 32};
  const std::vector<double> dftl = {0.0, 0.25, 0.5, 0.75, 0.9};
  const std::vector<double> lengths = {0.25, 0.125, 0.06};
  struct Cell {
    double length, bending, dftl;
    int substeps;
    double number = 0.0;
    bool capped = false;  // the steps asked for more than the column's: alpha = 1
    StabilityResult result;
  };
  std::vector<Cell> cells;
  for (double l : lengths)
    for (double d : dftl)
      for (double b : bending)
        for (int s : substeps) cells.push_back({l, b, d, s});
  std::fprintf(stderr, "soft hair: %zu runs of 2 s\n", cells.size());
  parallelFor(int(cells.size()), o.threads, [&](int i) {
    Cell& c = cells[i];
    Setting s;
    s.solver = "csm";
    s.model = StiffnessModel::Calibrated;
    s.bendingStiffness = float(c.bending * std::pow(c.length / 0.25, 3.0));
    s.windowLength = float(0.04 * c.length / 0.25);
    s.dftl = float(c.dftl);
    s.substeps = s.maxSubsteps = c.substeps;
    const Released r = releaseStrands(s, c.length, 2.0);
    c.result = r.result;
    c.number = r.stiffness.bendingNumber;
    c.capped = r.stiffness.plan.capped;
  });
  Csv csv({"length_m", "bending_stiffness", "bending_number", "dftl", "substeps", "capped",
           "blowup", "energy_ratio", "max_strain"});
  for (const Cell& c : cells) {
    csv.add(c.length).add(c.bending * std::pow(c.length / 0.25, 3.0)).add(c.number).add(c.dftl);
    csv.add(c.substeps).add(int(c.capped)).add(blowupName(c.result.blowup));
    csv.add(c.result.energyRatio).add(c.result.maxStrain);
    csv.endRow();
  }
  csv.write(o.out + "/soft_hair.csv");
  for (double l : lengths)
    for (double d : dftl) {
      std::fprintf(stderr,
                   "  %g cm, DFTL %.2f: energy ratio, steps a frame 1..32 (c: capped, alpha = 1)\n",
                   100.0 * l, d);
      for (double b : bending) {
        double number = 0.0;
        std::string row;
        for (const Cell& c : cells)
          if (c.length == l && c.dftl == d && c.bending == b) {
            number = c.number;
            char cell[16];
            std::snprintf(cell, sizeof cell, " %5.2f%s", c.result.energyRatio,
                          c.capped ? "c" : " ");
            row += cell;
          }
        std::fprintf(stderr, "    B/(gL^3) %.2e:%s\n", number, row.c_str());
      }
    }
}

}  // namespace csm::bench
