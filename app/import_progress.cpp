#include "app/import_progress.h"

#include <cstdio>

namespace csm {

void ImportProgressPrinter::operator()(std::string_view stage, double done) {
  const auto now = Clock::now();
  if (stage == "reading" && done == 0.0) {  // an import begins
    start_ = last_ = now;
    stage_.clear();
  }
  if (now - start_ < std::chrono::seconds(1) ||
      (stage == stage_ && now - last_ < std::chrono::milliseconds(500)))
    return;
  last_ = now;
  stage_ = stage;
  std::fprintf(stderr, "csmhair: importing the groom: %.*s, %.0f %%\n", int(stage.size()),
               stage.data(), 100.0 * done);
}

}  // namespace csm
