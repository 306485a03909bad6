// The torture map's far ends on the GPU solver, on the real GL driver (llvmpipe where there is
// no GPU): the cells and criteria of tests/cpu/torture_test.cpp (tests/torture_cases.h), in
// float. [jump] is the head turned 90 deg between two frames.
#include <catch2/catch.hpp>

#include "sim/gpu/gpu_solver.h"
#include "tests/gpu/gl_fixture.h"
#include "tests/gpu/gpu_solver_fixture.h"
#include "tests/torture_cases.h"

using namespace csm;

TEST_CASE("GPU torture map: sim.dt 1/240 and 1/24 s", "[gpu][torture][dt][long_run]") {
  test::checkTortureAxis(test::gpuSolver, "gpu", "dt");
}

TEST_CASE("GPU torture map: 1 and 8 substeps", "[gpu][torture][substeps][one_path]") {
  test::checkTortureAxis(test::gpuSolver, "gpu", "substeps");
}

TEST_CASE("GPU torture map: the narrowest and widest stiffness windows",
          "[gpu][torture][window][long_run]") {
  test::checkTortureAxis(test::gpuSolver, "gpu", "window");
}

TEST_CASE("GPU torture map: wind 0 and 50 m/s", "[gpu][torture][wind][one_path]") {
  test::checkTortureAxis(test::gpuSolver, "gpu", "wind");
}

TEST_CASE("GPU torture map: every head motion at 180 deg (cm) and 10 Hz",
          "[gpu][torture][motion][long_run]") {
  test::checkTortureAxis(test::gpuSolver, "gpu", "motion");
}

TEST_CASE("GPU torture map: the head turned 90 deg between two frames",
          "[gpu][torture][jump][one_path]") {
  test::checkTortureAxis(test::gpuSolver, "gpu", "jump");
}
