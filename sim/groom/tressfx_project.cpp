#include "sim/groom/tressfx_project.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string_view>
#include <vector>

#include "sim/base/obj_text.h"
#include "sim/groom/tressfx.h"

namespace csm::io {
namespace {

// TressFX integrates once a frame at 60 Hz, keeping (1 - damping) of each particle's velocity.
inline constexpr double kTressFxStep = 1.0 / 60.0;

// A .tfxsim file's "key value" lines for the report: those csmhair has a meaning for, in its own
// terms (damping as sim.damping's rate), and the rest as they are. Both empty when the file
// cannot be read.
struct SimValues {
  std::vector<std::string> mapped;
  std::string unused;
  bool read = false;
};

SimValues simValues(const std::string& path) {
  SimValues out;
  std::string error;
  const auto bytes = detail::readFileBytes(path, 1 << 20, &error);
  if (!bytes) return out;
  out.read = true;
  const std::string_view text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  detail::LineCursor lines(text);
  size_t line = 0;
  std::string_view raw;
  while (lines.next(line, raw)) {
    const auto t = detail::objTokens(raw, 3);
    if (t.size() < 2 || t[0] == "version") continue;
    double value = 0.0;
    if (t[0] == "damping" && detail::parseNumber(t[1], value) && value >= 0.0 && value < 1.0) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "damping %s is sim.damping %.2f /s in csmhair's terms (%.3f of the velocity "
                    "kept a 60 Hz step); the preset's sim.damping is used",
                    std::string(t[1]).c_str(), -std::log(1.0 - value) / kTressFxStep, 1.0 - value);
      out.mapped.push_back(text);
      continue;
    }
    out.unused += (out.unused.empty() ? "" : ", ") + std::string(t[0]) + " " + std::string(t[1]);
  }
  return out;
}

bool parseCount(std::string_view text, uint32_t& out) {
  long value = 0;
  if (!detail::parseIndex(text, value) || value < 0 || value > long(kMaxFollowHairs)) return false;
  out = uint32_t(value);
  return true;
}

bool parseNonNegative(std::string_view text, float& out) {
  double value = 0.0;
  if (!detail::parseNumber(text, value) || !std::isfinite(value) || value < 0.0) return false;
  out = float(value);
  return true;
}

}  // namespace

GroomReadResult readTressFxProject(std::span<const std::byte> bytes, const std::string& path) {
  namespace fs = std::filesystem;
  GroomReadResult result;
  const fs::path dir = fs::path(path).parent_path();
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  auto fail = [&](size_t line, const std::string& message) {
    result.error = path + ":" + std::to_string(line) + ": " + message;
    return result;
  };
  Groom groom;
  detail::LineCursor lines(detail::withoutBom(text));
  size_t line = 0, pieces = 0;
  std::string_view raw;
  std::vector<std::string> unused;
  size_t shapes = 0;
  while (lines.next(line, raw)) {
    if (raw.find('\0') != std::string_view::npos)
      return fail(line, "a NUL byte; a project is text");
    if (!raw.empty() && raw[0] == '#') continue;
    const auto t = detail::objTokens(raw);
    if (t.empty()) continue;
    const std::string word(t[0]);
    if (hasExtension(word, ".tfx")) {
      const std::string piece = (dir / word).string();
      GroomReadResult r = readTressFx(piece);
      if (!r.groom) return fail(line, "piece " + word + ": " + r.error);
      // The follow hairs a guide, their roots' radius and tip separation (TressFX's defaults
      // where the line stops short).
      Groom::FollowHairs follow;
      if (t.size() > 1 && !parseCount(t[1], follow.count))
        return fail(line, "the follow-hair count \"" + std::string(t[1]) +
                              "\" is not a whole number from 0 to " +
                              std::to_string(kMaxFollowHairs));
      if (t.size() > 2 && !parseNonNegative(t[2], follow.radius))
        return fail(line, "the follow hairs' radius \"" + std::string(t[2]) +
                              "\" is not a number of at least 0");
      if (t.size() > 3 && !parseNonNegative(t[3], follow.tipSeparation))
        return fail(line, "the follow hairs' tip separation \"" + std::string(t[3]) +
                              "\" is not a number of at least 0");
      for (size_t s = 0; s < r.groom->strandCount(); ++s) {
        const Groom& g = *r.groom;
        groom.addStrand(std::vector<glm::vec3>(g.points.begin() + g.first[s],
                                               g.points.begin() + g.first[s + 1]));
        groom.addStrandData(g, s);
        // A piece without held tips among pieces with them: its strands' tips are free.
        if (g.tipHeld.empty()) groom.tipHeld.push_back(0);
        groom.follow.push_back(follow);
      }
      result.repair.add(r.repair);
      ++pieces;
      if (t.size() > 4) {
        const std::string sim(t[4]);
        const SimValues values = simValues((dir / sim).string());
        for (const std::string& m : values.mapped) result.mapped.push_back(sim + ": " + m);
        if (!values.read)
          unused.push_back(sim + ": not found");
        else if (!values.unused.empty())
          unused.push_back(sim + ": " + values.unused +
                           " (csmhair's sim.* stiffness has its own meaning)");
      }
    } else if (word == "collision_sphere") {
      double v[4];
      for (int k = 0; k < 4; ++k)
        if (t.size() != 5 || !detail::parseNumber(t[size_t(k) + 1], v[k]) || !std::isfinite(v[k]))
          return fail(line, "collision_sphere wants four numbers: x y z radius");
      if (!(v[3] > 0.0)) return fail(line, "the collision sphere's radius is not above 0");
      result.spheres.push_back({glm::vec3(float(v[0]), float(v[1]), float(v[2])), float(v[3])});
    } else if (word == "collision_capsule") {
      ++shapes;
    } else if (word != "version" && word != "project_name") {
      unused.push_back("line " + std::to_string(line) + ": " + std::string(raw.substr(0, 80)));
    }
  }
  if (pieces == 0) return fail(lines.lastNonBlank(), "no piece (a line naming a .tfx file)");
  if (std::none_of(groom.follow.begin(), groom.follow.end(),
                   [](const Groom::FollowHairs& f) { return f.count > 0; }))
    groom.follow.clear();
  // Tips held in some pieces only: a flag a strand for all of them, none when no piece holds any.
  if (groom.tipHeld.size() != groom.strandCount()) groom.tipHeld.clear();
  bool anyHeld = false;
  for (const uint8_t h : groom.tipHeld) anyHeld = anyHeld || h != 0;
  if (!anyHeld) groom.tipHeld.clear();
  if (shapes > 0)
    unused.push_back(std::to_string(shapes) +
                     (shapes == 1 ? " collision capsule" : " collision capsules") +
                     ": csmhair's head is spheres or a shape "
                     "(collision.head_shape), the project's spheres are taken as its spheres");
  result.unused = std::move(unused);
  result.facesMinusZ = true;
  result.groom = std::move(groom);
  return result;
}

}  // namespace csm::io
