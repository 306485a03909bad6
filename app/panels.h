// The viewer's Dear ImGui panels. Parameter widgets are built by one loop over the parameter
// table (sim/param/sim_params.h), grouped by `group` ("Simulation|Collision" is a tree node inside
// the Simulation header), with the description as tooltip: no per-field UI code (SPlisHSPlasH's
// GUI/imgui/imguiParameters.cpp works the same way).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/params.h"

namespace csm {

class Viewer;

// What the panels remember between frames.
struct PanelState {
  bool showHelp = true;
  bool showStats = true;
  bool showTimeline = true;
  float bakeSeconds = 2.0f;
  int cacheMb = 512;
  char exportDir[256] = "hair_sequence";
  std::string saveAsName;
  int selectedPreset = -1;
  std::vector<std::filesystem::path> presetDirs, presetFiles;
  double presetsScannedAt = -1e9;  // ImGui time of the last scan of the preset folders
};

// The parameter table as a tree of groups, in the table's order.
struct ParamGroup {
  std::string name;
  std::vector<const PresetParam*> params;
  std::vector<ParamGroup> children;
};
const std::vector<ParamGroup>& paramGroups();

enum class ParamEdit {
  None,
  Apply,   // apply the edited config now
  Pending  // a parameter that regrows the hair is being dragged: apply on release
};
// One widget for one parameter, chosen by its type, editing `config` in place.
ParamEdit paramWidget(const PresetParam& p, Preset& preset);

// Every panel and banner of one frame; widgets that change the scene call
// Viewer::applyConfig (or the viewer's other actions).
void drawPanels(Viewer& viewer, PanelState& state);

void drawParameterPanel(Viewer& viewer, PanelState& state);
void drawPresetSection(Viewer& viewer, PanelState& state);
void drawStatsPanel(Viewer& viewer, PanelState& state);
void drawTimelinePanel(Viewer& viewer, PanelState& state);
void drawHelpPanel(PanelState& state);
void drawBanners(Viewer& viewer);

// Keys and mouse actions, for the help panel (and the README).
struct Shortcut {
  const char* keys;
  const char* action;
};
const std::vector<Shortcut>& shortcuts();

}  // namespace csm
