// Solvers by name: "cpu" (the reference, sim/cpu) or "gpu" (sim/gpu, which needs a current GL
// 4.3 context). Here, above both, so that the CPU solver's library needs no GL.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "sim/core/solver.h"

namespace csm {

// Makes a solver by name ("cpu", "gpu"), null with a message when it cannot: what the viewer's
// simulation thread calls with its GL context current (makeSolver below, or a test's own).
using SolverByName = std::function<std::unique_ptr<Solver>(const std::string& name, std::string* error)>;

// Null with a message when the name is unknown or the solver cannot start.
std::unique_ptr<Solver> makeSolver(const std::string& name, std::string* error);

// The GPU solver, if the current GL context can run it; null with a message otherwise.
std::unique_ptr<Solver> makeGpuSolver(std::string* error);

}  // namespace csm
