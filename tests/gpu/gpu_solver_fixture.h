#pragma once
// A GPU solver on the shared test context (tests/gpu/gl_fixture.h).
#include <memory>
#include <string>

#include <catch2/catch.hpp>

#include "sim/gpu/gpu_solver.h"
#include "tests/gpu/gl_fixture.h"

namespace csm::test {

// REQUIREs that the solver could be made, with the reason in the log.
inline std::unique_ptr<GpuSolver> gpuSolver() {
  glContext();
  std::string error;
  std::unique_ptr<GpuSolver> gpu = GpuSolver::create(&error);
  INFO(error);
  REQUIRE(gpu);
  return gpu;
}

}  // namespace csm::test
