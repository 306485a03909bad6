// A solver run on its own (tests, tools) is handed its head as Simulation hands its solver one
// (sim/run/simulation.h): built from the scene's config, handed before the reset. A solver builds
// none itself (sim/head/head_model.h, SolverHead).
#pragma once

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/core/pose.h"
#include "sim/core/solver.h"

namespace csm {

// Hands `solver` the head `config` asks for, then resets it on `groom` at head pose `head`.
// Throws std::runtime_error naming the file where head.mesh cannot be read
// (HeadModel::require): the caller's scene is one it has checked.
void resetWithHead(Solver& solver, const Groom& groom, const Config& config,
                   const Pose& head = Pose{});

}  // namespace csm
