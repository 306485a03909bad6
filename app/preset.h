// Presets: a JSON file holding a whole scene (app/preset_value.h): what it is called, the
// simulated scene (sim/core/config.h) and how it is viewed (render/view_config.h). Every key is a
// parameter of the one list (app/params.h), which reading and writing walk.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "app/preset_value.h"

namespace csm {

struct PresetErrors {
  std::vector<std::string> messages;  // each names the file and the JSON path or byte offset
  bool empty() const { return messages.empty(); }
  std::string text() const;  // one message a line
};

// Reads a preset over the defaults. `source` names the file in messages.
// Returns false, with every problem found in `errors`, when the preset is not valid; `out`
// is then left unchanged.
// The checks between parameters (sim/run/scene_checks.h) and of the machine's capacity run too.
bool parsePreset(std::string_view text, const std::string& source, Preset& out,
                 PresetErrors& errors);
bool loadPreset(const std::string& path, Preset& out, PresetErrors& errors);

// The whole preset as JSON, every parameter present, nested by the keys' dots.
nlohmann::json presetToJson(const Preset& c);
// Writes a temporary file beside `path`, flushes it, then renames it over `path`: a crash or a
// full disk never leaves a truncated preset.
bool savePreset(const std::string& path, const Preset& c, std::string* error);

// The preset compiled into the binary, so the program runs with no files.
std::string_view defaultPresetText();
Preset defaultPreset();

}  // namespace csm
