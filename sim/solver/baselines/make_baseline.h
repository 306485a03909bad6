// The baselines by name, for the benchmarks and the tests: the one file that knows every
// baseline (each knows only their base, sim/solver/baselines/baseline_solver.h).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "sim/solver/baselines/baseline_solver.h"

namespace csm {

// "ms-explicit", "ms-implicit", "pbd", "ftl"; null for an unknown name.
std::unique_ptr<BaselineSolver> makeBaseline(std::string_view name, const BaselineParams& params);
std::vector<std::string> baselineNames();

}  // namespace csm
