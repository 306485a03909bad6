#include "sim/preset.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <glm/geometric.hpp>

#include <nlohmann/json.hpp>

#include "sim/params.h"

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
  for (const Param& p : params()) {
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

std::string unknownKeyMessage(const std::string& prefix, const std::string& key) {
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

void readObject(const json& obj, const std::string& prefix, const std::string& source, Config& c,
                PresetErrors& errors) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    std::string key = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (const Param* p = findParam(key)) {
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

bool parsePreset(std::string_view text, const std::string& source, Config& out,
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
  }
  if (!doc.is_object()) {
    errors.messages.push_back(source + ": the top level must be a JSON object");
    return false;
  }
  Config c = out;
  size_t before = errors.messages.size();
  readObject(doc, "", source, c, errors);
  for (const std::string& e : crossCheck(c)) errors.messages.push_back(source + ": " + e);
  if (errors.messages.size() != before) return false;
  std::string capacity = checkCapacity(c);
  if (!capacity.empty()) {
    errors.messages.push_back(source + ": " + capacity);
    return false;
  }
  out = std::move(c);
  return true;
}

bool loadPreset(const std::string& path, Config& out, PresetErrors& errors) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    errors.messages.push_back(path + ": cannot open the file");
    return false;
  }
  std::stringstream ss;
  ss << in.rdbuf();
  return parsePreset(ss.str(), path, out, errors);
}

std::vector<std::string> crossCheck(const Config& c) {
  std::vector<std::string> e;
  const HairstyleConfig& h = c.hairstyle;
  if (h.minParticles > h.maxParticles)
    e.push_back("hairstyle.min_particles: " + std::to_string(h.minParticles) +
                " is greater than hairstyle.max_particles " + std::to_string(h.maxParticles));
  if (h.lengthMin > h.lengthMax)
    e.push_back("hairstyle.length_min: " + std::to_string(h.lengthMin) +
                " is greater than hairstyle.length_max " + std::to_string(h.lengthMax));
  if (h.particlesPerStrand != 0 && h.particlesPerStrand < 3)
    e.push_back("hairstyle.particles_per_strand: " + std::to_string(h.particlesPerStrand) +
                " is too few; use 0 (by length) or at least 3");
  if (c.sim.pinned >= (h.particlesPerStrand ? h.particlesPerStrand : h.minParticles))
    e.push_back("sim.pinned: " + std::to_string(c.sim.pinned) +
                " pins every particle of the shortest strand");
  if (glm::length(c.wind.direction) < 1e-6f && c.wind.strength > 0.0f)
    e.push_back("wind.direction: must not be zero when wind.strength is above 0");
  return e;
}

std::string checkCapacity(const Config& c) {
  const HairstyleConfig& h = c.hairstyle;
  // A groom file's size is checked by its reader (sim/io) before anything is allocated.
  if (!h.file.empty()) return {};
  const uint64_t perStrand = h.particlesPerStrand > 0 ? h.particlesPerStrand : h.maxParticles;
  const uint64_t particles = uint64_t(h.strands) * perStrand;
  // The CPU reference holds about 400 bytes a particle (double state, prefix sums, grid);
  // the GPU solver about 200 bytes of buffers.
  const uint64_t bytes = particles * 400;
  const uint64_t pages = static_cast<uint64_t>(sysconf(_SC_PHYS_PAGES));
  const uint64_t pageSize = static_cast<uint64_t>(sysconf(_SC_PAGE_SIZE));
  const uint64_t memory = pages * pageSize;
  if (particles > (1ull << 27))
    return "hairstyle.strands: " + std::to_string(h.strands) + " strands of up to " +
           std::to_string(perStrand) + " particles (" + std::to_string(particles) +
           " particles) exceed the limit of 134217728 particles";
  if (memory > 0 && bytes > memory / 2)
    return "hairstyle.strands: " + std::to_string(h.strands) + " strands of up to " +
           std::to_string(perStrand) + " particles need about " + std::to_string(bytes >> 20) +
           " MiB, more than half of this machine's " + std::to_string(memory >> 20) + " MiB";
  return {};
}

json presetToJson(const Config& c) {
  json root = json::object();
  for (const Param& p : params()) setPath(root, p.key, paramToJson(p, c));
  return root;
}

bool savePreset(const std::string& path, const Config& c, std::string* error) {
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

Config defaultConfig() {
  Config c;
  PresetErrors errors;
  if (!parsePreset(defaultPresetText(), "<built-in default preset>", c, errors)) {
    // The built-in preset is checked by the tests; reaching this is a build error.
    std::fputs(errors.text().c_str(), stderr);
  }
  return c;
}

std::string resolveRelative(const std::string& baseDir, const std::string& path) {
  if (path.empty() || baseDir.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (std::filesystem::path(baseDir) / path).lexically_normal().string();
}

}  // namespace csm
