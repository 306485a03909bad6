// libFuzzer target: text as a preset (app/preset.h's parsePreset: the JSON, every value's
// range, the checks between parameters and of capacity), then the scene it describes built on
// the CPU (sim/run/simulation.h: the groom grown on the head, the hair state and the solver's
// regions, the volume grid) and one frame stepped.
//
// Files the preset names (head.mesh, hairstyle.file) are pointed at a path that does not
// exist, so their error paths run but nothing on the machine is read: the readers have their
// own targets (fuzz_obj, fuzz_cyhair, fuzz_tressfx).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/preset.h"
#include "sim/solver/cpu_solver.h"
#include "sim/run/simulation.h"
#include "tests/fuzz/fuzz_common.h"

namespace {

using csm::fuzz::fail;
using nlohmann::json;

// Walks the document as parsePreset does (a key is its parents' keys joined by dots) and
// points head.mesh and hairstyle.file elsewhere. True when it changed anything.
bool redirectFiles(json& object, const std::string& prefix) {
  bool changed = false;
  for (auto it = object.begin(); it != object.end(); ++it) {
    const std::string key = prefix.empty() ? it.key() : prefix + "." + it.key();
    if ((key == "head.mesh" || key == "hairstyle.file") && it->is_string() &&
        !it->get<std::string>().empty()) {
      const std::string name = it->get<std::string>();
      const std::string ext = name.size() >= 4 ? name.substr(name.size() - 4) : "";
      *it = "/nonexistent/fuzz" + (ext == ".obj" || ext == "hair" || ext == ".tfx" ? ext : "");
      changed = true;
    } else if (it->is_object()) {
      changed = redirectFiles(*it, key) || changed;
    }
  }
  return changed;
}

const csm::Preset& basePreset() {
  static const csm::Preset preset = csm::defaultPreset();
  return preset;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  std::string rewritten;
  json doc = json::parse(text.begin(), text.end(), nullptr, false);
  if (!doc.is_discarded() && doc.is_object() && redirectFiles(doc, "")) {
    rewritten = doc.dump();
    text = rewritten;
  }

  csm::Preset preset = basePreset();
  csm::PresetErrors errors;
  const bool ok = csm::parsePreset(text, "fuzz.json", preset, errors);
  if (ok != errors.empty()) fail("parsePreset's result disagrees with its messages");
  for (const std::string& m : errors.messages)
    if (m.rfind("fuzz.json", 0) != 0) fail("a message does not name the file: " + m);
  if (!ok) return 0;

  // What the viewer saves must read back as the same preset.
  const std::string saved = csm::presetToJson(preset).dump(2);
  csm::Preset again = basePreset();
  csm::PresetErrors againErrors;
  if (!csm::parsePreset(saved, "saved.json", again, againErrors))
    fail("a saved preset does not read back:\n" + againErrors.text() + saved);
  if (csm::presetToJson(again) != csm::presetToJson(preset))
    fail("a saved preset reads back different:\n" + saved);

  // The harness's caps, not the product's (which allows a million strands, 2 m strands and
  // 256 steps a frame, checked by checkCapacity): they keep one execution near a millisecond.
  // Clamped rather than refused, so that the shipped presets (2000 strands) still build.
  csm::Config c = preset.scene;
  csm::HairstyleConfig& h = c.hairstyle;
  h.strands = std::min(h.strands, 8);
  h.lengthMin = std::min(h.lengthMin, 0.4f);
  h.lengthMax = std::min(h.lengthMax, 0.4f);
  c.sim.substeps = std::min(c.sim.substeps, 4);
  c.sim.maxSubsteps = std::min(c.sim.maxSubsteps, 4);
  c.sim.rotationIterations = std::min(c.sim.rotationIterations, 4);
  c.collision.iterations = std::min(c.collision.iterations, 4);
  c.collision.lists = std::min(c.collision.lists, 2);
  // The volume grid spans the roots grown by the longest strand; 4 cm cells keep it to
  // ~30 nodes an axis (the product allows 256, ~1 GB).
  c.collision.volumeCell = std::max(c.collision.volumeCell, 0.04f);
  // Fitting spheres to the field costs seconds a count (made once per count and then kept):
  // the harness fits at most 4.
  if (c.head.fitSpheres && c.head.spheres.size() > 4) c.head.spheres.resize(4);

  csm::Simulation sim(std::make_unique<csm::CpuSolver>());
  std::string error;
  if (!sim.load(c, "", &error)) {
    if (error.empty()) fail("Simulation::load failed without a message");
    return 0;
  }
  if (sim.counts().particles != sim.groom().pointCount())
    fail("the solver holds another particle count than the groom");
  sim.stepFrame();
  std::vector<glm::vec4> x;
  sim.readPositions(x);
  for (const glm::vec4& p : x)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail("a particle is not finite after one frame");
  return 0;
}
