#include <memory>
#include <string>

#include "sim/solver.h"

namespace csm {

std::unique_ptr<Solver> makeGpuSolver(std::string* error) {
  if (error) *error = "the GPU solver is not part of this build; use --solver cpu";
  return nullptr;
}

}  // namespace csm
