#include "render/interactive_budget.h"

#include <algorithm>
#include <cmath>

namespace csm {

void InteractiveBudget::measured(double ms, double budgetMs) {
  if (budgetMs <= 0.0) {
    extra_ = 1.0f;
    return;
  }
  if (!(ms > 0.0) || !std::isfinite(ms)) return;
  const double ratio = budgetMs / ms;
  if (ms > budgetMs) {
    // Over: in proportion (the extra strands are most of what grows), at least halved, so two
    // frames over bring a share that cannot fit down to nothing.
    const double next = double(extra_) * std::min(ratio, 0.5);
    extra_ = next < kLeast ? 0.0f : float(next);
  } else if (ms < kGrowUnder * budgetMs) {
    // Well under: toward what fits, at most doubled a frame; from nothing, a first few.
    const double next = std::max(double(extra_) * std::min(kGrowUnder * ratio, 2.0), 2.0 * kLeast);
    extra_ = float(std::min(next, 1.0));
  }
}

}  // namespace csm
