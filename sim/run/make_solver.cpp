#include "sim/run/make_solver.h"

#include "sim/solver/cpu_solver.h"
#include "sim/gpu/gpu_solver.h"
#include "sim/gpu/pass_profile.h"

namespace csm {

std::unique_ptr<Solver> makeSolver(const std::string& name, std::string* error) {
  if (name == "cpu") return std::make_unique<CpuSolver>();
  if (name == "gpu") return GpuSolver::start(error);
  if (error) *error = "unknown solver \"" + name + "\" (solvers: cpu, gpu)";
  return nullptr;
}

void clearPassProfile() {
  gpu::pass_profile::clear();
}

std::string passProfileTable(long frames) {
  return gpu::pass_profile::table(frames);
}

}  // namespace csm
