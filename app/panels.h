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
  float layoutWidth = 0, layoutHeight = 0;  // the work area the panels were last laid out for
  float bakeSeconds = 2.0f;
  int cacheMb = 512;
  char exportDir[256] = "hair_sequence";
  std::string saveAsName;
  int selectedPreset = -1;
  std::vector<std::filesystem::path> presetDirs, presetFiles;
  double presetsScannedAt = -1e9;  // ImGui time of the last scan of the preset folders
};

// A rectangle of the work area (the window less any menu bar), in pixels from its top-left.
struct PanelRect {
  float x = 0, y = 0, width = 0, height = 0;
};

// Where the panels open, tiled so that none covers another: Parameters down the left side,
// the Timeline along the bottom to its right, Help (folded to its title bar unless there is
// room for it) and Stats in a column on the right above the Timeline, and the rest, in the
// middle, left to the hair (`view`: the banners go there). Pure, from the work area's size
// and the font's size in pixels (15: the viewer's font; heights are counted in rows of it).
struct PanelLayout {
  PanelRect parameters, stats, help, timeline, view;
  bool helpOpen = false;  // help unfolded: its rectangle holds the shortcuts, not the title bar
};
PanelLayout panelLayout(float width, float height, float fontSize = 15.0f);
// The next window's position and size, always, from a rectangle of the main viewport's work area.
void setNextWindowRect(const PanelRect& r);

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

void drawPresetSection(Viewer& viewer, PanelState& state);
// Each panel's rectangle is applied when `place` (the first frame and after the window's size
// changed); the user moves and resizes them in between.
void drawParameterPanel(Viewer& viewer, PanelState& state, const PanelLayout& layout, bool place);
void drawStatsPanel(Viewer& viewer, PanelState& state, const PanelLayout& layout, bool place);
void drawTimelinePanel(Viewer& viewer, PanelState& state, const PanelLayout& layout, bool place);
void drawHelpPanel(PanelState& state, const PanelLayout& layout, bool place);
void drawBanners(Viewer& viewer, const PanelLayout& layout);

// Keys and mouse actions, for the help panel (and the README).
struct Shortcut {
  const char* keys;
  const char* action;
};
const std::vector<Shortcut>& shortcuts();

}  // namespace csm
