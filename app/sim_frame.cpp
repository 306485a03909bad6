#include "app/sim_frame.h"

#include "sim/run/simulation.h"

namespace csm {

std::string solverLabel(const SimFrame& frame) {
  return frame.solverVariant.empty() ? frame.solver
                                     : frame.solver + " (" + frame.solverVariant + ")";
}

void takeFigures(const Simulation& sim, SimFrame& frame) {
  const SolverDiagnostics& diagnostics = sim.diagnostics();
  frame.solver = std::string(sim.solverName());
  frame.solverVariant = diagnostics.variant();
  frame.config = sim.config();
  frame.groomReport = sim.groomReport();
  frame.strands = sim.counts().strands;
  frame.particles = sim.counts().particles;
  frame.drawnStrands = sim.drawnStrands();
  frame.carriedFrames = sim.carriedFrames();
  frame.clip = sim.scene().clip;
  frame.clipCuts = sim.clipCuts();
  frame.stiffness = diagnostics.stiffness();
  frame.memory = diagnostics.memoryUse();
}

}  // namespace csm
