#include "app/scene_setup.h"

#include <filesystem>

#include "app/params.h"
#include "app/preset.h"
#include "sim/groom/read_common.h"
#include "sim/motion/clip.h"
#include "sim/run/scene_checks.h"

namespace csm {

bool isGroomFile(const std::string& path) {
  for (const char* ext : {".hair", ".tfx", ".tfxproj", ".obj", ".data", ".bin", ".ply"})
    if (io::hasExtension(path, ext)) return true;
  return false;
}

bool setupScene(const Options& options, SceneSetup& out, std::string* errors) {
  namespace fs = std::filesystem;
  out.preset = defaultPreset();
  out.baseDir.clear();
  out.source = "<built-in default preset>";
  if (!options.preset.empty()) {
    if (isGroomFile(options.preset)) {
      // A groom opened directly: the default scene with the groom instead of the generator.
      out.preset.name = fs::path(options.preset).stem().string();
      HairstyleConfig& h = out.preset.scene.hairstyle;
      h.file = fs::absolute(options.preset).lexically_normal().string();
      h.strands = 1000000;  // every strand of the file
      h.maxParticles = 32;
      out.source = options.preset;
    } else {
      PresetErrors pe;
      Preset c = out.preset;
      if (!loadPreset(options.preset, c, pe)) {
        if (errors) *errors = pe.text();
        return false;
      }
      out.preset = c;
      out.source = options.preset;
      out.baseDir = fs::absolute(options.preset).parent_path().string();
    }
  }
  return applySets(options.sets, out, errors);
}

bool applySets(const std::vector<std::pair<std::string, std::string>>& sets, SceneSetup& out,
               std::string* errors) {
  std::string msgs;
  for (const auto& [key, value] : sets) {
    const PresetParam* p = findParam(key);
    if (!p) {
      std::string near;
      for (const PresetParam& q : params())
        if (q.key.substr(0, q.key.find('.')) == key.substr(0, key.find('.')))
          near += (near.empty() ? "" : ", ") + std::string(q.key);
      msgs +=
          "--set " + key + "=" + value + ": unknown parameter" +
          (near.empty() ? std::string(" (see --list-params)") : "; keys in this group: " + near) +
          "\n";
      continue;
    }
    std::string err = paramFromText(*p, out.preset, value);
    if (!err.empty()) msgs += "--set " + key + "=" + value + ": " + err + "\n";
  }
  if (msgs.empty()) {
    for (const std::string& e : crossCheck(out.preset.scene))
      msgs += out.source + " with --set: " + e + "\n";
    std::string capacity = checkCapacity(out.preset.scene);
    if (!capacity.empty()) msgs += capacity + "\n";
  }
  if (msgs.empty()) {
    std::string headError;
    out.head = HeadModel::build(out.preset.scene, &headError);
    if (!out.head) msgs += out.source + (sets.empty() ? ": " : " with --set: ") + headError + "\n";
  }
  if (msgs.empty() && !out.preset.scene.motion.clip.empty()) {
    // The clip too, before anything is simulated: its file and line when bad.
    std::string clipError;
    if (!MotionClip::load(out.preset.scene.motion, out.baseDir,
                          glm::dvec3(out.preset.scene.head.pivot), &clipError))
      msgs += out.source + (sets.empty() ? ": " : " with --set: ") + clipError + "\n";
  }
  if (!msgs.empty()) {
    if (errors) *errors = msgs;
    return false;
  }
  return true;
}

}  // namespace csm
