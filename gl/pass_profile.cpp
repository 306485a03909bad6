#include "gl/pass_profile.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <vector>

#include "gl/draw.h"

namespace csm::gl::pass_profile {
namespace {

struct Row {
  double ms = 0.0;
  long runs = 0;
};
std::map<std::string, Row>& rows() {
  static std::map<std::string, Row> r;
  return r;
}

}  // namespace

bool enabled() {
  static const bool on = [] {
    const char* v = std::getenv("CSM_PASS_PROFILE");
    return v && *v && std::string(v) != "0";
  }();
  return on;
}

void clear() {
  rows().clear();
}

namespace detail {

void finish() {
  ::csm::gl::finish();
}

double nowMs() {
  using Clock = std::chrono::steady_clock;
  return std::chrono::duration<double, std::milli>(Clock::now().time_since_epoch()).count();
}

void add(const std::string& path, double ms) {
  Row& r = rows()[path];
  r.ms += ms;
  ++r.runs;
}

}  // namespace detail

std::string table(long frames) {
  if (rows().empty() || frames <= 0) return {};
  std::vector<std::pair<std::string, Row>> sorted(rows().begin(), rows().end());
  std::sort(sorted.begin(), sorted.end(),
            [](const auto& a, const auto& b) { return a.second.ms > b.second.ms; });
  double total = 0.0;
  for (const auto& [path, r] : sorted) total += r.ms;
  std::string out = "| pass | ms a frame | share | runs a frame |\n|---|---|---|---|\n";
  char line[256];
  for (const auto& [path, r] : sorted) {
    std::snprintf(line, sizeof line, "| %s | %.2f | %.1f %% | %.1f |\n", path.c_str(),
                  r.ms / double(frames), 100.0 * r.ms / std::max(total, 1e-12),
                  double(r.runs) / double(frames));
    out += line;
  }
  std::snprintf(line, sizeof line, "| all passes | %.2f | 100 %% | |\n", total / double(frames));
  out += line;
  return out;
}

}  // namespace csm::gl::pass_profile
