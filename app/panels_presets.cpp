// The Presets section: list, load, save, save as, revert, reload shaders.
#include <imgui.h>
#include <imgui_stdlib.h>

#include "app/panels.h"
#include "app/viewer_presets.h"

namespace csm {
namespace {

const ImVec4 kYellow{1.0f, 0.8f, 0.3f, 1.0f};
constexpr double kRescanSeconds = 2.0;

void rescan(const PanelView& view, PanelState& state) {
  const double now = ImGui::GetTime();
  if (now - state.presetsScannedAt < kRescanSeconds) return;
  state.presetsScannedAt = now;
  const std::filesystem::path selected =
      state.selectedPreset >= 0 && state.selectedPreset < int(state.presetFiles.size())
          ? state.presetFiles[size_t(state.selectedPreset)]
          : std::filesystem::path();
  state.presetDirs = presetDirectories(view.document.path());
  state.presetFiles = listPresets(state.presetDirs);
  state.selectedPreset = -1;
  for (size_t i = 0; i < state.presetFiles.size(); ++i)
    if (state.presetFiles[i] == selected) state.selectedPreset = int(i);
}

// "default.json", or "other/dir/default.json" when it is not in the first folder.
std::string shortName(const std::filesystem::path& file, const PanelState& state) {
  if (!state.presetDirs.empty() && file.parent_path() == state.presetDirs.front())
    return file.filename().string();
  return file.parent_path().filename().string() + "/" + file.filename().string();
}

}  // namespace

void drawPresetSection(const PanelView& view, PanelRequests& ask, PanelState& state) {
  if (!ImGui::CollapsingHeader("Presets", ImGuiTreeNodeFlags_DefaultOpen)) return;
  rescan(view, state);
  ImGui::Text("%s", view.document.current().name.c_str());
  const std::vector<std::string_view> changed = view.document.modifiedKeys();
  if (!changed.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(kYellow, "modified (%zu)", changed.size());
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      ImGui::TextUnformatted("Differs from the preset as loaded:");
      for (std::string_view k : changed) ImGui::BulletText("%.*s", int(k.size()), k.data());
      ImGui::EndTooltip();
    }
  }
  ImGui::TextDisabled(
      "%s", view.document.path().empty() ? "built-in preset" : view.document.path().c_str());

  if (state.presetFiles.empty()) {
    ImGui::TextWrapped(
        "No presets found: looked beside the opened preset, in ./presets, beside the program "
        "and in the source tree.");
  } else if (ImGui::BeginListBox("##presets",
                                 ImVec2(-1.0f, ImGui::GetTextLineHeightWithSpacing() * 5.5f))) {
    std::error_code ec;
    const std::filesystem::path open =
        view.document.path().empty() ? std::filesystem::path()
                                     : std::filesystem::weakly_canonical(view.document.path(), ec);
    for (size_t i = 0; i < state.presetFiles.size(); ++i) {
      const bool current = !open.empty() && open == state.presetFiles[i];
      const std::string name = shortName(state.presetFiles[i], state) + (current ? "  (open)" : "");
      if (ImGui::Selectable(name.c_str(), state.selectedPreset == int(i),
                            ImGuiSelectableFlags_AllowDoubleClick)) {
        state.selectedPreset = int(i);
        if (ImGui::IsMouseDoubleClicked(0)) ask.loadPreset(state.presetFiles[i].string());
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", state.presetFiles[i].c_str());
    }
    ImGui::EndListBox();
  }

  const bool picked =
      state.selectedPreset >= 0 && state.selectedPreset < int(state.presetFiles.size());
  ImGui::BeginDisabled(!picked);
  if (ImGui::Button("Load"))
    ask.loadPreset(state.presetFiles[size_t(state.selectedPreset)].string());
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Load the selected preset (or double-click it).");
  ImGui::SameLine();
  ImGui::BeginDisabled(view.document.path().empty());
  if (ImGui::Button("Save")) ask.save();
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(
        "Write the scene over the opened preset (Ctrl+S). Written to a temporary "
        "file and renamed, so a crash never leaves half a preset.");
  ImGui::SameLine();
  ImGui::BeginDisabled(changed.empty());
  if (ImGui::Button("Revert")) ask.revert();
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Back to the preset as loaded or last saved.");
  ImGui::SameLine();
  if (ImGui::Button("Reload shaders")) ask.reloadShaders();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Recompile the shaders from disk (F5); a shader that fails keeps the old "
        "program and shows the log.");

  ImGui::InputTextWithHint("##saveas", "new_preset.json", &state.saveAsName);
  ImGui::SameLine();
  ImGui::BeginDisabled(state.saveAsName.empty());
  if (ImGui::Button("Save as")) {
    const std::filesystem::path path =
        saveAsPath(state.saveAsName, view.document.path(), state.presetDirs);
    if (ask.saveAs(path.string())) {
      state.saveAsName.clear();
      state.presetsScannedAt = -1e9;
    }
  }
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("A bare name goes beside the opened preset (or into the presets folder).");
}

}  // namespace csm
