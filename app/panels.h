// The viewer's Dear ImGui panels. Parameter widgets are built by one loop over the parameter
// table (sim/param/sim_params.h), grouped by `group` ("Simulation|Collision" is a tree node inside
// the Simulation header), with the description as tooltip: no per-field UI code (SPlisHSPlasH's
// GUI/imgui/imguiParameters.cpp works the same way).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/params.h"
#include "app/preset_document.h"
#include "app/scene_view.h"
#include "app/sim_thread.h"
#include "app/viewer_message.h"
#include "app/viewer_stats.h"

namespace csm {

class SimControls;

// What the panels show, read from the viewer once a frame (Viewer::panelView). Views, not
// copies, of what the viewer keeps: a change a widget asks for shows where it is read after it.
struct PanelView {
  const SimFrame& frame;                         // the latest frame: counts, stiffness, timeline
  const PresetDocument& document;                // the preset: its name, file, what differs
  const ViewerStats& stats;                      // the UI's frame times, the drawn strands
  const std::vector<ViewerMessage>& messages;    // oldest first
  const std::vector<std::string>& presetErrors;  // the preset problems window's lines
  const std::string& presetErrorsNote;           // and its title
  const PictureStatus& picture;                  // the renderer's state, quality, shader log
  SimThread::ImportStatus import;                // a long groom import's stage and share done
  const std::string& renderer;                   // the window's GL renderer
  bool loading = false;                          // a preset is being opened
  bool vsync = false;
};

// What the panels ask of the viewer; the Viewer implements it and the panels see nothing else
// of it. Every change of the scene goes through applyConfig, as a test's would.
class PanelRequests {
 public:
  // Pause, step, reset and the timeline.
  virtual SimControls& controls() = 0;
  // The copy of the preset the parameter widgets edit in place before applyConfig.
  virtual Preset& editedPreset() = 0;
  virtual bool applyConfig(const Preset& next) = 0;
  virtual bool loadPreset(const std::string& path) = 0;
  virtual bool save() = 0;
  virtual bool saveAs(const std::string& path) = 0;
  virtual void revert() = 0;
  virtual void frameHead() = 0;
  virtual void resetView() = 0;
  virtual void resetHead() = 0;
  virtual bool reloadShaders() = 0;
  // What the window shows, panels included, into a file named by the time in the current folder.
  virtual void screenshot() = 0;
  virtual void dismissPresetErrors() = 0;
  virtual void dismissShaderLog() = 0;
  virtual void setVsync(bool on) = 0;

 protected:
  ~PanelRequests() = default;
};

// What the panels remember between frames.
struct PanelState {
  bool showHelp = true;
  bool showStats = true;
  bool showTimeline = true;
  bool showMotion = true;
  std::string clipPath;                     // the Motion panel's path field
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

// Every panel and banner of one frame: they show `view`; widgets that change the scene ask
// `ask` (applyConfig, or the viewer's other requests).
void drawPanels(const PanelView& view, PanelRequests& ask, PanelState& state);

void drawPresetSection(const PanelView& view, PanelRequests& ask, PanelState& state);
// Each panel's rectangle is applied when `place` (the first frame and after the window's size
// changed); the user moves and resizes them in between.
void drawParameterPanel(const PanelView& view, PanelRequests& ask, PanelState& state,
                        const PanelLayout& layout, bool place);
void drawStatsPanel(const PanelView& view, PanelRequests& ask, PanelState& state,
                    const PanelLayout& layout, bool place);
void drawTimelinePanel(const PanelView& view, PanelRequests& ask, PanelState& state,
                       const PanelLayout& layout, bool place);
void drawHelpPanel(PanelState& state, const PanelLayout& layout, bool place);
// The Motion panel: the clip that moves the character (motion.clip), what was inferred of it, its
// joints, and its frames on the timeline.
void drawMotionPanel(const PanelView& view, PanelRequests& ask, PanelState& state,
                     const PanelLayout& layout, bool place);
void drawBanners(const PanelView& view, PanelRequests& ask, const PanelLayout& layout);

// Keys and mouse actions, for the help panel (and the README).
struct Shortcut {
  const char* keys;
  const char* action;
};
const std::vector<Shortcut>& shortcuts();

}  // namespace csm
