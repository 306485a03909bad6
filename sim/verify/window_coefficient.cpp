#include "sim/verify/window_coefficient.h"

#include <cmath>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/solver/cpu_probe.h"
#include "sim/verify/solver_head.h"

namespace csm {

double measureWindowCoefficient(int w) {
  const double l = 0.01;
  const int n = 8 * w + 24;
  Groom straight;
  std::vector<glm::vec3> pts;
  for (int i = 0; i < n; ++i) pts.emplace_back(float(i * l), 0.0f, 0.0f);
  straight.addStrand(pts);
  Config c;
  c.sim.stiffnessModel = StiffnessModel::Paper;
  c.sim.stiffnessWindow = w;
  c.sim.stiffness = 1.0f;
  c.sim.pinned = 0;
  c.sim.gravity = glm::vec3(0.0f);
  c.sim.damping = 0.0f;
  c.sim.strainLimiting = false;
  c.sim.rotationIterations = 16;
  c.collision.mode = CollisionMode::Off;
  c.wind.strength = 0.0f;
  // mu(kappa) / (kappa w l)^4 = c_w + d (kappa w l)^2: two wavenumbers give c_w. The slope
  // kappa * amplitude stays small enough that the rotations' nonlinearity is far below mu.
  auto ratio = [&](double kwl) {
    const double kappa = kwl / (w * l);
    const double amplitude = 1e-6 / kappa;
    CpuSolver solver;
    resetWithHead(solver, straight, c, Pose{});
    // The wave is set in double, as the solver holds it (SolverState::write would round it to
    // float and move the measure off the table's digits).
    CpuProbe probe(solver);
    std::vector<glm::dvec3> x = probe.positions();
    for (int i = 0; i < n; ++i) x[i] = glm::dvec3(i * l, amplitude * std::sin(kappa * i * l), 0.0);
    probe.setPositions(x);
    probe.step(1e-3, Pose{});
    // The middle particles, whose goals no clipped region and no clipped per-region mass
    // reaches (3w from either end): there g = (1 - mu) u exactly.
    double gu = 0.0, uu = 0.0;
    for (int i = 3 * w + 1; i < n - 3 * w - 1; ++i) {
      const double u = amplitude * std::sin(kappa * i * l);
      gu += probe.positions()[i].y * u;
      uu += u * u;
    }
    return (1.0 - gu / uu) / std::pow(kwl, 4.0);
  };
  const double r1 = ratio(0.1), r2 = ratio(0.2);
  return (4.0 * r1 - r2) / 3.0;
}

}  // namespace csm
