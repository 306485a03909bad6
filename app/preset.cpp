#include "app/preset.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "app/params.h"
#include "sim/run/scene_checks.h"

namespace csm {
namespace {

using nlohmann::json;

// Line and column (1-based) of a byte offset, for parse errors.
std::string lineColumn(std::string_view text, size_t byte) {
  size_t line = 1, col = 1;
  for (size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return std::to_string(line) + ":" + std::to_string(col);
}

// Keys of the parameter table one level below `prefix` ("" = top level).
std::vector<std::string> childKeys(const std::string& prefix) {
  std::vector<std::string> keys;
  for (const PresetParam& p : params()) {
    std::string_view k = p.key;
    if (!prefix.empty()) {
      if (k.size() <= prefix.size() + 1 || k.substr(0, prefix.size()) != prefix ||
          k[prefix.size()] != '.')
        continue;
      k = k.substr(prefix.size() + 1);
    }
    std::string head(k.substr(0, k.find('.')));
    if (std::find(keys.begin(), keys.end(), head) == keys.end()) keys.push_back(head);
  }
  return keys;
}

size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t prev = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t cur = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, prev + (a[i - 1] != b[j - 1] ? 1u : 0u)});
      prev = cur;
    }
  }
  return row[b.size()];
}

// Keys that were renamed: the message names the new one.
std::string movedKey(const std::string& key) {
  if (key == "hairstyle.follow_count") return "render.children";
  if (key == "hairstyle.follow_spread") return "render.child_radius";
  return {};
}

std::string unknownKeyMessage(const std::string& prefix, const std::string& key) {
  const std::string moved = movedKey(prefix.empty() ? key : prefix + "." + key);
  if (!moved.empty()) return "no longer read: it is now " + moved;
  std::vector<std::string> keys = childKeys(prefix);
  std::string msg = "unknown key";
  std::string best;
  size_t bestDist = 3;
  for (const std::string& k : keys) {
    size_t d = editDistance(k, key);
    if (d < bestDist) bestDist = d, best = k;
  }
  if (!best.empty()) msg += " (did you mean \"" + best + "\"?)";
  msg += "; keys here: ";
  for (size_t i = 0; i < keys.size(); ++i) msg += (i ? ", " : "") + keys[i];
  return msg;
}

void readObject(const json& obj, const std::string& prefix, const std::string& source, Preset& c,
                PresetErrors& errors) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    std::string key = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (const PresetParam* p = findParam(key)) {
      std::string err = paramFromJson(*p, c, it.value());
      if (!err.empty()) {
        // Sphere errors begin with their index: keep the path continuous.
        std::string sep = (!err.empty() && err[0] == '[') ? "" : ": ";
        errors.messages.push_back(source + ": " + key + sep + err);
      }
    } else if (it.value().is_object() && !childKeys(key).empty()) {
      readObject(it.value(), key, source, c, errors);
    } else {
      errors.messages.push_back(source + ": " + key + ": " + unknownKeyMessage(prefix, it.key()));
    }
  }
}

void setPath(json& root, std::string_view key, json value) {
  json* node = &root;
  size_t start = 0;
  while (true) {
    size_t dot = key.find('.', start);
    std::string part(key.substr(start, dot == std::string_view::npos ? dot : dot - start));
    if (dot == std::string_view::npos) {
      (*node)[part] = std::move(value);
      return;
    }
    node = &(*node)[part];
    start = dot + 1;
  }
}

}  // namespace

std::string PresetErrors::text() const {
  std::string s;
  for (const std::string& m : messages) s += m + "\n";
  return s;
}

bool parsePreset(std::string_view text, const std::string& source, Preset& out,
                 PresetErrors& errors) {
  json doc;
  try {
    doc = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    size_t byte = e.byte > 0 ? e.byte - 1 : 0;
    std::string what = e.what();
    // nlohmann's text starts with "[json.exception.parse_error.101] parse error at line ..."
    size_t colon = what.find(": ");
    std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
    errors.messages.push_back(source + ":" + lineColumn(text, byte) + " (byte " +
                              std::to_string(byte) + "): invalid JSON: " + detail);
    return false;
  } catch (const json::exception& e) {
    // Well-formed JSON that nlohmann cannot hold, such as a number beyond double's range
    // (out_of_range.406, "1e999"): no byte offset comes with it.
    std::string what = e.what();
    size_t bracket = what.find("] ");
    std::string detail = bracket == std::string::npos ? what : what.substr(bracket + 2);
    errors.messages.push_back(source + ": invalid JSON: " + detail);
    return false;
  }
  if (!doc.is_object()) {
    errors.messages.push_back(source + ": the top level must be a JSON object");
    return false;
  }
  Preset c = out;
  size_t before = errors.messages.size();
  readObject(doc, "", source, c, errors);
  for (const std::string& e : crossCheck(c.scene)) errors.messages.push_back(source + ": " + e);
  if (errors.messages.size() != before) return false;
  std::string capacity = checkCapacity(c.scene);
  if (!capacity.empty()) {
    errors.messages.push_back(source + ": " + capacity);
    return false;
  }
  out = std::move(c);
  return true;
}

bool loadPreset(const std::string& path, Preset& out, PresetErrors& errors) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    errors.messages.push_back(path + ": cannot open the file");
    return false;
  }
  std::stringstream ss;
  ss << in.rdbuf();
  // head.mesh is relative to the preset's folder (checked on parsing, so set before).
  Preset c = out;
  c.scene.head.meshDir = std::filesystem::absolute(path).parent_path().string();
  if (!parsePreset(ss.str(), path, c, errors)) return false;
  out = std::move(c);
  return true;
}

json presetToJson(const Preset& c) {
  json root = json::object();
  for (const PresetParam& p : params()) setPath(root, p.key, paramToJson(p, c));
  return root;
}

bool savePreset(const std::string& path, const Preset& c, std::string* error) {
  namespace fs = std::filesystem;
  std::string text = presetToJson(c).dump(2) + "\n";
  std::string tmp = path + ".tmp" + std::to_string(::getpid());
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) {
    if (error) *error = tmp + ": cannot create the file";
    return false;
  }
  bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  ok = std::fflush(f) == 0 && ok;
  ok = ::fsync(fileno(f)) == 0 && ok;
  ok = std::fclose(f) == 0 && ok;
  if (!ok) {
    std::remove(tmp.c_str());
    if (error) *error = path + ": writing failed; the old file is untouched";
    return false;
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    if (error) *error = path + ": cannot replace the file: " + ec.message();
    return false;
  }
  return true;
}

Preset defaultPreset() {
  Preset c;
  PresetErrors errors;
  if (!parsePreset(defaultPresetText(), "<built-in default preset>", c, errors)) {
    // The built-in preset is checked by the tests; reaching this is a build error.
    std::fputs(errors.text().c_str(), stderr);
  }
  return c;
}

}  // namespace csm
