#include "sim/run/make_solver.h"

#include <atomic>

#include "sim/solver/baselines/make_baseline.h"
#include "sim/solver/cpu_solver.h"
#include "sim/gpu/gpu_solver.h"

namespace csm {

namespace {
std::atomic<long> made{0};
}  // namespace

long solversMade() {
  return made.load();
}

std::unique_ptr<Solver> makeSolver(const std::string& name, std::string* error) {
  ++made;
  if (name == "cpu") return std::make_unique<CpuSolver>();
  if (name == "gpu") return GpuSolver::start(error);
  if (error) *error = "unknown solver \"" + name + "\" (solvers: cpu, gpu)";
  return nullptr;
}

SolverMaker solverMaker(const std::string& name, const BaselineParams& params) {
  return [name, params]() -> std::unique_ptr<Solver> {
    if (name == "cpu" || name == "csm")
      return std::make_unique<CpuSolver>(CpuSolver::RegionSums::Prefix);
    if (name == "csm-direct") return std::make_unique<CpuSolver>(CpuSolver::RegionSums::Direct);
    if (name == "gpu") return GpuSolver::start(nullptr);
    return makeBaseline(name, params);
  };
}

std::unique_ptr<Simulation> makeSimulation(const std::string& name, std::string* error,
                                           const SolverByName& make) {
  std::unique_ptr<Solver> solver = make(name, error);
  if (!solver) return nullptr;
  return std::make_unique<Simulation>(std::move(solver));
}

}  // namespace csm
