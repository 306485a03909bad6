// The flawed import of tests/import_cases.h on the GPU solver: float positions, the strain
// measured on the GPU.
#include <catch2/catch.hpp>

#include "tests/gpu/gpu_solver_fixture.h"
#include "tests/import_cases.h"

TEST_CASE("GPU: the flawed groom's 30 frames", "[gpu][import]") {
  auto gpu = csm::test::gpuSolver();
  csm::test::checkImportedRun(*gpu, 1e-4);
}
