// Solvers by name: "cpu" (the reference, sim/solver/cpu_solver.h) or "gpu" (sim/gpu, which needs
// a current GL 4.3 context). Here, above both and in a library of its own, so that nothing below
// it needs GL.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "sim/core/solver.h"

namespace csm {

// Makes a solver by name ("cpu", "gpu"), null with a message when it cannot: what the viewer's
// simulation thread calls with its GL context current (makeSolver below, or a test's own).
using SolverByName =
    std::function<std::unique_ptr<Solver>(const std::string& name, std::string* error)>;

// Null with a message when the name is unknown or the solver cannot start.
std::unique_ptr<Solver> makeSolver(const std::string& name, std::string* error);

// The GPU solver's pass profile (CSM_PASS_PROFILE=1 in the environment, sim/gpu/pass_profile.h),
// here so that a program reaches the GPU solver only through this factory. Forgets what was timed
// so far: a run calls it after its set-up, so that the table holds its frames only.
void clearPassProfile();
// Every pass's ms a frame over `frames` frames, slowest first; empty when nothing was timed (the
// profile off, or no GPU solver ran).
std::string passProfileTable(long frames);

}  // namespace csm
