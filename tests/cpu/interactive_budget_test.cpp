// Interactive quality's frame budget (render/interactive_budget.h): the share of children and
// followers follows the measured draw times, from the simulated strands alone.
#include <catch2/catch.hpp>

#include "render/interactive_budget.h"

using csm::InteractiveBudget;

TEST_CASE("interactive quality's budget grows the extra strands under it and sheds them over it",
          "[render][quick]") {
  InteractiveBudget b;
  CHECK(b.extra() == 0.0f);  // the simulated strands alone, until a frame is measured
  SECTION("well under the budget: doubling a frame up to everything") {
    b.measured(5.0, 33.0);
    CHECK(b.extra() == Approx(2.0 * InteractiveBudget::kLeast));
    for (int i = 0; i < 8; ++i) b.measured(5.0, 33.0);
    CHECK(b.extra() == 1.0f);
    SECTION("in the band between: held") {
      b.measured(30.0, 33.0);
      CHECK(b.extra() == 1.0f);
    }
    SECTION("over: in proportion, at least halved, nothing below the least share") {
      b.measured(66.0, 33.0);
      CHECK(b.extra() == Approx(0.5));
      b.measured(34.0, 33.0);
      CHECK(b.extra() == Approx(0.25));
      for (int i = 0; i < 4; ++i) b.measured(400.0, 33.0);
      CHECK(b.extra() == 0.0f);
    }
  }
  SECTION("the simulated strands alone over the budget: nothing more is tried") {
    for (int i = 0; i < 20; ++i) b.measured(140.0, 33.0);
    CHECK(b.extra() == 0.0f);
  }
  SECTION("no budget: everything; a frame with no time measured changes nothing") {
    b.measured(0.0, 33.0);
    CHECK(b.extra() == 0.0f);
    b.measured(500.0, 0.0);
    CHECK(b.extra() == 1.0f);
  }
}
