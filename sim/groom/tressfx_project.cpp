#include "sim/groom/tressfx_project.h"

#include <filesystem>
#include <string_view>
#include <vector>

#include "sim/base/obj_text.h"
#include "sim/groom/tressfx.h"

namespace csm::io {
namespace {

// A .tfxsim file's "key value" lines, as one line of the report ("" when it cannot be read).
std::string simValues(const std::string& path) {
  std::string error;
  const auto bytes = detail::readFileBytes(path, 1 << 20, &error);
  if (!bytes) return {};
  const std::string_view text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  detail::LineCursor lines(text);
  size_t line = 0;
  std::string_view raw;
  std::string values;
  while (lines.next(line, raw)) {
    const auto t = detail::objTokens(raw, 3);
    if (t.size() < 2 || t[0] == "version") continue;
    values += (values.empty() ? "" : ", ") + std::string(t[0]) + " " + std::string(t[1]);
  }
  return values;
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
      for (size_t s = 0; s < r.groom->strandCount(); ++s) {
        const Groom& g = *r.groom;
        groom.addStrand(std::vector<glm::vec3>(g.points.begin() + g.first[s],
                                               g.points.begin() + g.first[s + 1]));
        groom.addStrandData(g, s);
        // A piece without held tips among pieces with them: its strands' tips are free.
        if (g.tipHeld.empty()) groom.tipHeld.push_back(0);
      }
      result.repair.add(r.repair);
      ++pieces;
      std::string note = word + ": ";
      note += t.size() > 1 ? std::string(t[1]) + " follow hairs a guide" : "no follow hairs";
      if (t.size() > 3)
        note += " (radius " + std::string(t[2]) + ", tip separation " + std::string(t[3]) + ")";
      note += ": csmhair draws hairstyle.guides' followers and render.children instead";
      unused.push_back(note);
      if (t.size() > 4) {
        const std::string values = simValues((dir / std::string(t[4])).string());
        unused.push_back(std::string(t[4]) + ": " +
                         (values.empty() ? std::string("not found")
                                         : values + " (csmhair's sim.* stiffness and damping "
                                                    "have their own meaning)"));
      }
    } else if (word == "collision_sphere" || word == "collision_capsule") {
      ++shapes;
    } else if (word != "version" && word != "project_name") {
      unused.push_back("line " + std::to_string(line) + ": " + std::string(raw.substr(0, 80)));
    }
  }
  if (pieces == 0) return fail(lines.lastNonBlank(), "no piece (a line naming a .tfx file)");
  // Tips held in some pieces only: a flag a strand for all of them, none when no piece holds any.
  if (groom.tipHeld.size() != groom.strandCount()) groom.tipHeld.clear();
  bool anyHeld = false;
  for (const uint8_t h : groom.tipHeld) anyHeld = anyHeld || h != 0;
  if (!anyHeld) groom.tipHeld.clear();
  if (shapes > 0)
    unused.push_back(std::to_string(shapes) +
                     " collision shapes (in the files' units): the head's shape is csmhair's own "
                     "(collision.head_shape, head.spheres)");
  result.unused = std::move(unused);
  result.facesMinusZ = true;
  result.groom = std::move(groom);
  return result;
}

}  // namespace csm::io
