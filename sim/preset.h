// Presets: a JSON file holding a whole scene. Every key is a parameter of sim/params.h.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "sim/config.h"

namespace csm {

struct PresetErrors {
  std::vector<std::string> messages;  // each names the file and the JSON path or byte offset
  bool empty() const { return messages.empty(); }
  std::string text() const;  // one message a line
};

// Reads a preset over the defaults. `source` names the file in messages.
// Returns false, with every problem found in `errors`, when the preset is not valid; `out`
// is then left unchanged.
bool parsePreset(std::string_view text, const std::string& source, Config& out,
                 PresetErrors& errors);
bool loadPreset(const std::string& path, Config& out, PresetErrors& errors);

// Checks that hold between parameters (ranges of single values are checked on reading).
std::vector<std::string> crossCheck(const Config& c);

// Refuses scenes the machine cannot hold, before anything is allocated. Empty when fine.
std::string checkCapacity(const Config& c);

// The whole scene as JSON, every parameter present, nested by the keys' dots.
nlohmann::json presetToJson(const Config& c);
// Writes a temporary file beside `path`, flushes it, then renames it over `path`: a crash or a
// full disk never leaves a truncated preset.
bool savePreset(const std::string& path, const Config& c, std::string* error);

// The preset compiled into the binary, so the program runs with no files.
std::string_view defaultPresetText();
Config defaultConfig();

// Directory of the preset file a config was read from ("" for the built-in preset); relative
// groom paths are resolved against it.
std::string resolveRelative(const std::string& baseDir, const std::string& path);

}  // namespace csm
