// Solvers by name: "cpu" (the reference, sim/solver/cpu_solver.h) or "gpu" (sim/gpu, which needs
// a current GL 4.3 context). Here, above both and in a library of its own, so that nothing below
// it needs GL.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "sim/core/solver.h"
#include "sim/solver/baselines/baseline_solver.h"
#include "sim/run/simulation.h"

namespace csm {

// Makes a solver by name ("cpu", "gpu"), null with a message when it cannot: what the viewer's
// simulation thread calls with its GL context current (makeSolver below, or a test's own).
using SolverByName =
    std::function<std::unique_ptr<Solver>(const std::string& name, std::string* error)>;

// Null with a message when the name is unknown or the solver cannot start.
std::unique_ptr<Solver> makeSolver(const std::string& name, std::string* error);

// The calls to makeSolver in this process so far: a render from a shot's cache makes none.
long solversMade();

// Every kind of solver by name, for the benchmarks and the measures: "cpu" (or "csm"), "csm-direct"
// (the CPU solver summing its regions directly), "gpu" (none without a context), and the
// baselines (sim/solver/baselines/make_baseline.h) with `params`; none for an unknown name.
SolverMaker solverMaker(const std::string& name, const BaselineParams& params = {});

// A simulation (no scene loaded yet) on the solver `make` makes by `name`: what the app runs, so
// that it never holds a solver. Null with the maker's message when there is none.
std::unique_ptr<Simulation> makeSimulation(const std::string& name, std::string* error,
                                           const SolverByName& make = makeSolver);

}  // namespace csm
