// The window coefficient c_w of sim/stiffness.h, measured on the CPU solver for w = 1..32,
// beside the table the calibrated stiffness model uses.
#include <cstdio>

#include "app/bench/bench.h"
#include "app/bench/csv.h"
#include "sim/cpu/cpu_solver.h"
#include "sim/stiffness.h"

namespace csm::bench {

void runWindow(const Options& o) {
  Csv csv({"w", "measured", "table", "relative_difference"});
  for (int w = 1; w <= 32; ++w) {
    const double measured = measureWindowCoefficient(w), table = windowCoefficient(w);
    csv.add(w).add(measured).add(table).add(table / measured - 1.0);
    csv.endRow();
    std::fprintf(stderr, "  w %2d  c_w measured %.6f  table %.6f  (%+.2e)\n", w, measured, table,
                 table / measured - 1.0);
  }
  csv.write(o.out + "/window_coefficient.csv");
}

}  // namespace csm::bench
