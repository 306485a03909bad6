#include <catch2/catch.hpp>

#include "sim/solver/cpu_solver.h"
#include "tests/live_params_check.h"

using namespace csm;

TEST_CASE("every live parameter changes the motion when changed live (CPU)", "[params][live]") {
  const test::LiveCheck check = test::checkLiveParams(std::make_unique<CpuSolver>());
  CHECK(check.tested.size() >= 33);
  INFO("no effect: " << Catch::Detail::stringify(check.noEffect));
  CHECK(check.noEffect.empty());
}
