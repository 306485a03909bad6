// The preset the window edits, as a document: what runs (current), what the widgets edit
// (edited), the preset as loaded or last saved (loaded) and its file. No window, no GL: the
// Viewer (app/viewer.h) applies edits to the simulation and says what happened.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "app/preset_value.h"

namespace csm {

class PresetDocument {
 public:
  // A preset opened from `path` (empty for the built-in one): current, edited and loaded.
  void opened(const Preset& preset, const std::string& path);
  // `next` runs now; the widgets show it.
  void applied(const Preset& next);
  // The widgets show what runs again (an edit refused).
  void discardEdits() { edited_ = current_; }

  const Preset& current() const { return current_; }
  Preset& edited() { return edited_; }
  const Preset& edited() const { return edited_; }
  const Preset& loaded() const { return loaded_; }
  const std::string& path() const { return path_; }

  // Writes what runs to `path` (never a truncated file: savePreset writes and renames) and
  // makes it the document's file and its loaded state. False with *error.
  bool saveAs(const std::string& path, std::string* error);
  // Parameters that differ from the loaded preset. Camera moves do not count (orbiting should
  // not nag), but saving stores the current view.
  std::vector<std::string_view> modifiedKeys() const;
  bool modified() const { return !modifiedKeys().empty(); }
  // "csmhair - NAME (PATH) *": the window's title.
  std::string title() const;

 private:
  Preset current_, edited_, loaded_;
  std::string path_;
};

}  // namespace csm
