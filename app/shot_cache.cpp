#include "app/shot_cache.h"

#include <cstdio>
#include <filesystem>
#include <span>

#include <nlohmann/json.hpp>

#include "app/preset.h"
#include "sim/base/file_io.h"
#include "sim/base/fnv.h"
#include "sim/run/cache_files.h"

namespace csm::shot_cache {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr uint64_t kMaxInputBytes = uint64_t(4) << 30;
constexpr uint64_t kMaxManifestBytes = uint64_t(64) << 20;

std::string hex(uint64_t v) {
  char text[24];
  std::snprintf(text, sizeof text, "%016llx", (unsigned long long)v);
  return text;
}

bool unhex(const json& j, uint64_t& out) {
  if (!j.is_string()) return false;
  const std::string s = j.get<std::string>();
  if (s.size() != 16) return false;
  char* end = nullptr;
  out = std::strtoull(s.c_str(), &end, 16);
  return end == s.c_str() + s.size();
}

}  // namespace

bool isCache(const std::string& dir) {
  std::error_code ec;
  return fs::is_directory(dir, ec) && fs::is_regular_file(fs::path(dir) / kManifestName, ec);
}

std::string framePath(const std::string& dir, long frame) {
  return (fs::path(dir) / "frames" / cache::frameName(frame)).string();
}

std::string statePath(const std::string& dir) {
  return (fs::path(dir) / kStateName).string();
}

bool fileHash(const std::string& path, uint64_t& out, std::string* error) {
  const std::optional<std::vector<std::byte>> bytes =
      io::detail::readFileBytes(path, kMaxInputBytes, error);
  if (!bytes) return false;
  out = fnv1a(bytes->data(), bytes->size());
  return true;
}

bool inputsOf(const Preset& preset, const std::string& baseDir, std::vector<CacheInput>& out,
              std::string* error) {
  out.clear();
  const Config& c = preset.scene;
  const std::pair<const char*, std::string> files[] = {
      {"hairstyle.file",
       c.hairstyle.file.empty() ? "" : resolveRelative(baseDir, c.hairstyle.file)},
      {"head.mesh", c.head.mesh.empty() ? "" : resolveRelative(c.head.meshDir, c.head.mesh)},
      {"head.torso_mesh", c.head.mesh.empty() || c.head.torsoMesh.empty()
                              ? ""
                              : resolveRelative(c.head.meshDir, c.head.torsoMesh)},
      {"motion.clip", c.motion.clip.empty() ? "" : resolveRelative(baseDir, c.motion.clip)},
  };
  for (const auto& [key, path] : files) {
    if (path.empty()) continue;
    CacheInput input{key, path, 0};
    std::string why;
    if (!fileHash(path, input.hash, &why)) {
      if (error) *error = std::string(key) + ": " + why;
      return false;
    }
    out.push_back(input);
  }
  return true;
}

bool writeManifest(const std::string& dir, const CacheManifest& m, std::string* error) {
  std::error_code ec;
  fs::create_directories(fs::path(dir) / "frames", ec);
  if (ec || !fs::is_directory(fs::path(dir) / "frames")) {
    if (error) *error = dir + ": cannot make the cache's folder" + (ec ? ": " + ec.message() : "");
    return false;
  }
  json inputs = json::array();
  for (const CacheInput& in : m.inputs)
    inputs.push_back({{"key", in.key}, {"path", in.path}, {"hash", hex(in.hash)}});
  const json doc = {
      {"csmhair_cache", cache::kCacheVersion},
      {"preset", presetToJson(m.preset)},
      {"source", m.source},
      {"base_dir", m.baseDir},
      {"solver", m.solver},
      {"dt", m.preset.scene.sim.dt},
      {"frames", m.frames},
      {"keyframe_every", m.keyframeEvery},
      {"groom",
       {{"strands", m.strands},
        {"particles", m.particles},
        {"drawn_strands", m.drawnStrands},
        {"drawn_points", m.drawnPoints},
        {"hash", hex(m.groomHash)}}},
      {"frame_bytes", cache::frameBytes(m.particles)},
      {"inputs", inputs},
  };
  const std::string text = doc.dump(2) + "\n";
  return io::detail::writeFileAtomically((fs::path(dir) / kManifestName).string(),
                                         std::as_bytes(std::span(text.data(), text.size())), error);
}

bool readManifest(const std::string& dir, CacheManifest& out, std::string* error) {
  const std::string path = (fs::path(dir) / kManifestName).string();
  auto fail = [&](const std::string& why) {
    if (error) *error = path + ": " + why;
    return false;
  };
  if (!isCache(dir)) {
    if (error) *error = dir + ": not a shot's cache (no folder with a " + kManifestName + ")";
    return false;
  }
  const std::optional<std::vector<std::byte>> bytes =
      io::detail::readFileBytes(path, kMaxManifestBytes, error);
  if (!bytes) return false;
  const std::string text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  const json doc = json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return fail("not a cache's manifest (invalid JSON)");
  if (!doc.contains("csmhair_cache") || !doc["csmhair_cache"].is_number_unsigned())
    return fail("not a cache's manifest (no csmhair_cache version)");
  const unsigned version = doc["csmhair_cache"].get<unsigned>();
  if (version != cache::kCacheVersion)
    return fail("a cache of format version " + std::to_string(version) + "; this csmhair reads " +
                std::to_string(cache::kCacheVersion) + ": bake it again");
  CacheManifest m;
  try {
    m.source = doc.at("source").get<std::string>();
    m.baseDir = doc.at("base_dir").get<std::string>();
    m.solver = doc.at("solver").get<std::string>();
    m.frames = doc.at("frames").get<long>();
    m.keyframeEvery = doc.at("keyframe_every").get<int>();
    const json& g = doc.at("groom");
    m.strands = g.at("strands").get<size_t>();
    m.particles = g.at("particles").get<size_t>();
    m.drawnStrands = g.at("drawn_strands").get<size_t>();
    m.drawnPoints = g.value("drawn_points", size_t(0));
    if (!unhex(g.at("hash"), m.groomHash)) return fail("groom.hash: not 16 hex digits");
    for (const json& in : doc.at("inputs")) {
      CacheInput input{in.at("key").get<std::string>(), in.at("path").get<std::string>(), 0};
      if (!unhex(in.at("hash"), input.hash)) return fail("inputs: a hash not of 16 hex digits");
      m.inputs.push_back(input);
    }
  } catch (const json::exception& e) {
    return fail(std::string("a field missing or of the wrong type: ") + e.what());
  }
  if (m.frames < 0 || m.keyframeEvery < 1 || (m.solver != "gpu" && m.solver != "cpu"))
    return fail("frames, keyframe_every or solver out of range");
  // The preset as a preset file is read, its relative files against the folder it came from.
  Preset preset = defaultPreset();
  preset.scene.head.meshDir = m.baseDir;
  PresetErrors errors;
  if (!doc.contains("preset") ||
      !parsePreset(doc["preset"].dump(), path + ": preset", preset, errors)) {
    if (error) *error = errors.empty() ? path + ": no preset" : errors.text();
    return false;
  }
  m.preset = preset;
  out = std::move(m);
  return true;
}

long completeFrames(const std::string& dir, const CacheManifest& m) {
  const uint64_t size = cache::frameBytes(m.particles);
  long n = 0;
  std::error_code ec;
  while (n < m.frames && fs::is_regular_file(framePath(dir, n + 1), ec) &&
         fs::file_size(framePath(dir, n + 1), ec) == size)
    ++n;
  return n;
}

bool matches(const CacheManifest& m, const GrownScene& grown, std::string* error) {
  auto fail = [&](const std::string& why) {
    if (error) *error = why;
    return false;
  };
  std::vector<CacheInput> now;
  if (!inputsOf(m.preset, m.baseDir, now, error)) return false;
  for (const CacheInput& was : m.inputs) {
    bool same = false;
    for (const CacheInput& is : now) same = same || (is.key == was.key && is.hash == was.hash);
    if (!same)
      return fail(was.key + " " + was.path +
                  ": the file changed since the bake (its bytes' hash differs): bake again");
  }
  const uint64_t hash = groomHash(grown);
  if (grown.groom->strandCount() != m.strands || grown.groom->pointCount() != m.particles ||
      hash != m.groomHash)
    return fail("the groom grown from the cache's preset (" +
                std::to_string(grown.groom->strandCount()) + " strands, " +
                std::to_string(grown.groom->pointCount()) + " particles, hash " + hex(hash) +
                ") is not the one baked (" + std::to_string(m.strands) + ", " +
                std::to_string(m.particles) + ", " + hex(m.groomHash) +
                "): another build of csmhair grows it otherwise; bake again");
  return true;
}

}  // namespace csm::shot_cache
