#include "app/sim_frame.h"

#include "sim/core/solver.h"
#include "sim/run/simulation.h"

namespace csm {

std::string solverLabel(const SimFrame& frame) {
  return frame.solverVariant.empty() ? frame.solver
                                     : frame.solver + " (" + frame.solverVariant + ")";
}

void takeFigures(const Simulation& sim, SimFrame& frame) {
  const Solver& solver = sim.solver();
  frame.solver = std::string(solver.name());
  frame.solverVariant = solver.variant();
  frame.config = sim.config();
  frame.groomReport = sim.groomReport();
  frame.strands = solver.strandCount();
  frame.particles = solver.particleCount();
  frame.drawnStrands = sim.drawnStrands();
  frame.carriedFrames = sim.carriedFrames();
  frame.stiffness = solver.stiffness();
  frame.memory = solver.memoryUse();
}

}  // namespace csm
