#include "app/preset_document.h"

#include "app/params.h"
#include "app/preset.h"

namespace csm {

void PresetDocument::opened(const Preset& preset, const std::string& path) {
  current_ = edited_ = loaded_ = preset;
  path_ = path;
}

void PresetDocument::applied(const Preset& next) {
  current_ = next;
  edited_ = current_;
}

bool PresetDocument::saveAs(const std::string& path, std::string* error) {
  if (!csm::savePreset(path, current_, error)) return false;
  loaded_ = current_;
  path_ = path;
  return true;
}

std::vector<std::string_view> PresetDocument::modifiedKeys() const {
  std::vector<std::string_view> keys;
  for (const PresetParam& p : params())
    if (p.group != "Camera" && !sameValue(p, loaded_, current_)) keys.push_back(p.key);
  return keys;
}

std::string PresetDocument::title() const {
  std::string t = "csmhair - " + current_.name;
  if (!path_.empty()) t += " (" + path_ + ")";
  if (modified()) t += " *";
  return t;
}

}  // namespace csm
