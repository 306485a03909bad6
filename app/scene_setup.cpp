#include "app/scene_setup.h"

#include <filesystem>

#include "sim/params.h"
#include "sim/preset.h"

namespace csm {

bool isGroomFile(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".hair" || ext == ".tfx";
}

bool setupScene(const Options& options, SceneSetup& out, std::string* errors) {
  namespace fs = std::filesystem;
  out.config = defaultConfig();
  out.baseDir.clear();
  out.source = "<built-in default preset>";
  if (!options.preset.empty()) {
    if (isGroomFile(options.preset)) {
      // A groom opened directly: the default scene with the groom instead of the generator.
      out.config.name = fs::path(options.preset).stem().string();
      out.config.hairstyle.file = fs::absolute(options.preset).lexically_normal().string();
      out.config.hairstyle.strands = 1000000;  // every strand of the file
      out.config.hairstyle.maxParticles = 32;
      out.source = options.preset;
    } else {
      PresetErrors pe;
      Config c = out.config;
      if (!loadPreset(options.preset, c, pe)) {
        if (errors) *errors = pe.text();
        return false;
      }
      out.config = c;
      out.source = options.preset;
      out.baseDir = fs::absolute(options.preset).parent_path().string();
    }
  }
  std::string msgs;
  for (const auto& [key, value] : options.sets) {
    const Param* p = findParam(key);
    if (!p) {
      std::string near;
      for (const Param& q : params())
        if (q.key.substr(0, q.key.find('.')) == key.substr(0, key.find('.')))
          near += (near.empty() ? "" : ", ") + std::string(q.key);
      msgs +=
          "--set " + key + "=" + value + ": unknown parameter" +
          (near.empty() ? std::string(" (see --list-params)") : "; keys in this group: " + near) +
          "\n";
      continue;
    }
    std::string err = paramFromText(*p, out.config, value);
    if (!err.empty()) msgs += "--set " + key + "=" + value + ": " + err + "\n";
  }
  if (msgs.empty()) {
    for (const std::string& e : crossCheck(out.config))
      msgs += out.source + " with --set: " + e + "\n";
    std::string capacity = checkCapacity(out.config);
    if (!capacity.empty()) msgs += capacity + "\n";
  }
  if (!msgs.empty()) {
    if (errors) *errors = msgs;
    return false;
  }
  return true;
}

}  // namespace csm
