// The stiffness window of the calibrated model (sim/solver/stiffness.h): the coefficient c_w it is
// calibrated with, measured on the CPU solver for w = 1..32 beside the table, and what the
// window length still does to a strand at a fixed bending stiffness.
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/vec4.hpp>

#include "tools/bench/bench.h"
#include "tools/bench/csv.h"
#include "sim/run/make_solver.h"
#include "sim/verify/window_coefficient.h"
#include "sim/solver/stiffness.h"

namespace csm::bench {
namespace {

// A 12 cm strand clamped over its first seventh, settled by strong damping: the tip's sag (m)
// and the turn (degrees) at the last held particle, between the held segment before it and the
// free one after.
struct Settled {
  double sag = 0.0, turn = 0.0, endFactor = 1.0;
};
Settled settle(int particles, float windowLength, double gravity) {
  Scene s = cantileverScene(particles, kCantileverLength, 1);
  s.config.sim.stiffnessModel = StiffnessModel::Calibrated;
  s.config.sim.windowLength = windowLength;
  s.config.sim.substeps = 1;
  s.config.sim.maxSubsteps = 256;
  s.config.sim.damping = float(kSettleDamping);
  s.config.sim.gravity = glm::vec3(0.0f, -float(gravity), 0.0f);
  SceneRunner run(solverMaker("cpu"), s);
  run.runTo(3.0);
  std::vector<glm::vec4> x;
  run.readPositions(x);
  Settled out;
  out.sag = double(x.front().y) - double(x.back().y);
  out.turn = clampTurnDegrees(s, x);
  const HairState st = makeHairState(s.groom, s.config.sim, Pose{});
  const Regions r = buildRegions(st, s.config.sim);
  out.endFactor = r.endFactor[0];
  return out;
}

}  // namespace

void runWindow(const Options& o) {
  Csv coefficients({"w", "measured", "table", "relative_difference"});
  for (int w = 1; w <= 32; ++w) {
    const double measured = measureWindowCoefficient(w), table = windowCoefficient(w);
    coefficients.add(w).add(measured).add(table).add(table / measured - 1.0);
    coefficients.endRow();
    std::fprintf(stderr, "  w %2d  c_w measured %.6f  table %.6f  (%+.2e)\n", w, measured, table,
                 table / measured - 1.0);
  }
  coefficients.write(o.out + "/window_coefficient.csv");

  // The window at a fixed bending stiffness: in the interior it only sets the rate k and the
  // steps; near the clamped root and the free tip it still shapes the strand.
  const double B = Config{}.sim.bendingStiffness;
  const double free = kCantileverLength * 6.0 / 7.0;
  Csv sags({"window_length_m", "particles", "gravity", "sag_mm", "beam_sag_mm", "clamp_turn_deg",
            "end_factor"});
  for (double g : {1.0, 9.81})
    for (int particles : {16, 32, 64})
      for (float length : {0.01f, 0.015f, 0.02f, 0.03f, 0.04f, 0.06f}) {
        const Settled settled = settle(particles, length, g);
        const double mm = 1000.0 * settled.sag;
        // Euler-Bernoulli: a clamped beam of the free length under its weight, small sag.
        const double beam = 1000.0 * g * std::pow(free, 4.0) / (8.0 * B);
        sags.add(double(length))
            .add(particles)
            .add(g)
            .add(mm)
            .add(beam)
            .add(settled.turn)
            .add(settled.endFactor);
        sags.endRow();
        std::fprintf(stderr,
                     "  window %4.1f cm  %2d particles  g %4.2f  sag %6.2f mm (beam %.2f)  end "
                     "factor %.3f  turn at "
                     "the clamp %5.1f deg\n",
                     100.0 * length, particles, g, mm, beam, settled.endFactor, settled.turn);
      }
  sags.write(o.out + "/window_sag.csv");
}

}  // namespace csm::bench
