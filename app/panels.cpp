#include "app/panels.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "app/sim_controls.h"
#include "sim/solver/stiffness.h"

namespace csm {
namespace {

const ImVec4 kRed{1.0f, 0.35f, 0.3f, 1.0f};
const ImVec4 kYellow{1.0f, 0.8f, 0.3f, 1.0f};

std::string str(std::string_view s) {
  return std::string(s);
}

ParamGroup& child(ParamGroup& parent, std::string_view name) {
  for (ParamGroup& g : parent.children)
    if (g.name == name) return g;
  parent.children.push_back(ParamGroup{str(name), {}, {}});
  return parent.children.back();
}

std::vector<ParamGroup> buildGroups() {
  ParamGroup root;
  for (const PresetParam& p : params()) {
    ParamGroup* g = &root;
    std::string_view rest = p.group;
    while (!rest.empty()) {
      const size_t bar = rest.find('|');
      g = &child(*g, rest.substr(0, bar));
      rest = bar == std::string_view::npos ? std::string_view() : rest.substr(bar + 1);
    }
    g->params.push_back(&p);
  }
  return root.children;
}

const char* effectText(Effect e) {
  switch (e) {
    case Effect::Live:
      return "takes effect on the next step";
    case Effect::Rebuild:
      return "regrows the hair (on release)";
    case Effect::Render:
      return "changes only the picture";
    case Effect::Info:
      return "describes the preset";
  }
  return "";
}

void paramTooltip(const PresetParam& p) {
  // Also on a greyed-out parameter: its description says which stiffness model it is for.
  if (!ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) return;
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
  ImGui::TextUnformatted(p.description.data(), p.description.data() + p.description.size());
  ImGui::TextDisabled("%s: %s; %s", str(p.key).c_str(), describeType(p).c_str(),
                      effectText(p.effect));
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

// Collects, over the items of one parameter's widget, whether it changed and whether the
// edit is finished (a click, Enter, or the release of a drag).
struct EditTracker {
  bool changed = false, finished = false;
  void item(bool itemChanged) {
    changed |= itemChanged;
    if (itemChanged && !ImGui::IsItemActive()) finished = true;
    if (ImGui::IsItemDeactivatedAfterEdit()) finished = true;
  }
};

ImGuiSliderFlags sliderFlags(const PresetParam& p) {
  return ImGuiSliderFlags_AlwaysClamp | (p.logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
}

float dragSpeed(const PresetParam& p) {
  return float(std::max(1e-4, (p.max - p.min) * 5e-4));
}

void sphereWidgets(const PresetParam& p, Preset& config, const std::string& label,
                   EditTracker& edit) {
  std::vector<Sphere>& spheres = p.ref<std::vector<Sphere>>(config);
  const bool open = ImGui::TreeNode(label.c_str());
  paramTooltip(p);
  if (!open) return;
  const float lo = float(p.min), hi = float(p.max);
  int remove = -1;
  for (size_t i = 0; i < spheres.size(); ++i) {
    ImGui::PushID(int(i));
    ImGui::Text("sphere %zu%s", i, i == 0 ? " (scalp)" : "");
    edit.item(ImGui::DragFloat3("centre", &spheres[i].center.x, 0.001f, lo, hi, "%.3f",
                                ImGuiSliderFlags_AlwaysClamp));
    edit.item(ImGui::DragFloat("radius", &spheres[i].radius, 0.001f, 0.001f, hi, "%.3f",
                               ImGuiSliderFlags_AlwaysClamp));
    if (i > 0) {
      ImGui::SameLine();
      if (ImGui::SmallButton("remove")) remove = int(i);
    }
    ImGui::PopID();
  }
  if (remove >= 0) {
    spheres.erase(spheres.begin() + remove);
    edit.changed = edit.finished = true;
  }
  if (ImGui::Button("add sphere")) {
    spheres.push_back(Sphere{{0.0f, -0.2f, 0.0f}, 0.05f});
    edit.changed = edit.finished = true;
  }
  ImGui::TreePop();
}

// What the stiffness the solver runs with comes to: steps, alpha, window in particles, and a
// warning when the stiffness asks for more steps than the step budget (sim.max_substeps) allows.
void drawStiffnessInfo(const PanelView& view) {
  const StiffnessInfo& info = view.frame.stiffness;
  if (info.strands == 0) return;
  ImGui::Indent();
  std::string text = stiffnessText(info);
  const SimConfig& sim = view.frame.config.sim;
  if (info.model == StiffnessModel::Calibrated) {
    char ei[64];
    std::snprintf(ei, sizeof ei, "; EI = B x density = %.3g N m^2",
                  double(sim.bendingStiffness) * double(sim.density));
    text += ei;
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "What this stiffness comes to in the running solver: steps per frame (calibrated: the "
        "most the stiffest strand needs for alpha <= 1), the pull alpha toward the goals per "
        "step, particles per side of a region, and the calibrated rate k = B / (c_w (w l)^4).");
  const std::string warning = stiffnessWarning(info);
  if (!warning.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kYellow);
    ImGui::TextWrapped("%s", warning.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::Unindent();
}

void drawGroupContents(const ParamGroup& group, const PanelView& view, PanelRequests& ask) {
  Preset& edited = ask.editedPreset();
  bool apply = false;
  for (const PresetParam* p : group.params) {
    const bool applies = p->applies(edited);
    if (!applies) ImGui::BeginDisabled();
    const ParamEdit e = paramWidget(*p, edited);
    if (!applies) ImGui::EndDisabled();
    if (e == ParamEdit::Apply) apply = true;
    if (applies && (p->key == "sim.window_length" || p->key == "sim.stiffness_window"))
      drawStiffnessInfo(view);
  }
  // Apply once, after the loop: applyConfig refreshes the edited copy.
  if (apply) ask.applyConfig(Preset(edited));
  for (const ParamGroup& sub : group.children) {
    if (ImGui::TreeNode(sub.name.c_str())) {
      drawGroupContents(sub, view, ask);
      ImGui::TreePop();
    }
  }
}

void drawMessages(const PanelView& view, size_t count) {
  const auto& messages = view.messages;
  const size_t first = messages.size() > count ? messages.size() - count : 0;
  for (size_t i = first; i < messages.size(); ++i) {
    const ViewerMessage& m = messages[i];
    const ImVec4 colour = m.level == MessageLevel::Error ? kRed
                          : m.level == MessageLevel::Warning
                              ? kYellow
                              : ImGui::GetStyleColorVec4(ImGuiCol_Text);
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextWrapped("%s", m.text.c_str());
    ImGui::PopStyleColor();
  }
}

// The keys' actions as buttons, for the mouse.
void drawControls(PanelRequests& ask) {
  if (ImGui::Button(ask.controls().paused() ? "Run" : "Pause"))
    ask.controls().setPaused(!ask.controls().paused());
  ImGui::SameLine();
  if (ImGui::Button("Step")) {
    ask.controls().setPaused(true);
    ask.controls().stepOnce();
  }
  ImGui::SameLine();
  if (ImGui::Button("Reset hair")) ask.controls().resetHair();
  ImGui::SameLine();
  if (ImGui::Button("Frame head")) ask.frameHead();
  ImGui::SameLine();
  if (ImGui::Button("Reset view")) ask.resetView();
  if (ImGui::Button("Undo head drag")) ask.resetHead();
  ImGui::SameLine();
  if (ImGui::Button("Screenshot")) ask.screenshot();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Saves what the window shows, panels included, in the current folder.");
}

}  // namespace

const std::vector<ParamGroup>& paramGroups() {
  static const std::vector<ParamGroup> groups = buildGroups();
  return groups;
}

ParamEdit paramWidget(const PresetParam& p, Preset& config) {
  ImGui::PushID(p.key.data(), p.key.data() + p.key.size());
  const std::string label = str(p.label);
  EditTracker edit;
  switch (p.type) {
    case ParamType::Bool:
      edit.item(ImGui::Checkbox(label.c_str(), &p.ref<bool>(config)));
      break;
    case ParamType::Int: {
      int& v = p.ref<int>(config);
      const int lo = int(p.min), hi = int(p.max);
      // Sliders need a range they can map to pixels; a seed's range is not one.
      if (p.logarithmic || p.max - p.min <= 100000.0)
        edit.item(ImGui::SliderInt(label.c_str(), &v, lo, hi, "%d", sliderFlags(p)));
      else
        edit.item(
            ImGui::DragInt(label.c_str(), &v, 1.0f, lo, hi, "%d", ImGuiSliderFlags_AlwaysClamp));
      break;
    }
    case ParamType::Float: {
      // Shown in the parameter's display unit (cm for lengths of strand), stored in SI.
      float& v = p.ref<float>(config);
      const float scale = float(p.displayScale);
      float shown = v * scale;
      const std::string format = p.unit.empty() ? "%.4g" : "%.4g " + str(p.unit);
      const bool changed = ImGui::SliderFloat(label.c_str(), &shown, float(p.min) * scale,
                                              float(p.max) * scale, format.c_str(), sliderFlags(p));
      if (changed) v = scale == 1.0f ? shown : shown / scale;
      edit.item(changed);
      break;
    }
    case ParamType::Vec3:
      edit.item(ImGui::DragFloat3(label.c_str(), &p.ref<glm::vec3>(config).x, dragSpeed(p),
                                  float(p.min), float(p.max), "%.3f",
                                  ImGuiSliderFlags_AlwaysClamp));
      break;
    case ParamType::Color:
      edit.item(
          ImGui::ColorEdit3(label.c_str(), &p.ref<glm::vec3>(config).x, ImGuiColorEditFlags_Float));
      break;
    case ParamType::Enum: {
      int& v = p.ref<int>(config);
      const std::string current =
          v >= 0 && v < int(p.options.size()) ? str(p.options[size_t(v)]) : std::to_string(v);
      bool picked = false;
      if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
        for (size_t i = 0; i < p.options.size(); ++i) {
          if (ImGui::Selectable(str(p.options[i]).c_str(), int(i) == v)) {
            picked = int(i) != v;
            v = int(i);
          }
        }
        ImGui::EndCombo();
      }
      edit.item(picked);
      if (picked) edit.finished = true;
      break;
    }
    case ParamType::String:
      edit.item(ImGui::InputText(label.c_str(), &p.ref<std::string>(config)));
      break;
    case ParamType::Spheres:
      sphereWidgets(p, config, label, edit);
      break;
  }
  if (p.type != ParamType::Spheres) paramTooltip(p);
  ImGui::PopID();
  if (p.effect == Effect::Rebuild) {
    if (edit.finished) return ParamEdit::Apply;
    return edit.changed ? ParamEdit::Pending : ParamEdit::None;
  }
  return edit.changed || edit.finished ? ParamEdit::Apply : ParamEdit::None;
}

void drawParameterPanel(const PanelView& view, PanelRequests& ask, PanelState& state,
                        const PanelLayout& layout, bool place) {
  if (place) setNextWindowRect(layout.parameters);
  if (!ImGui::Begin("Parameters")) {
    ImGui::End();
    return;
  }
  ImGui::PushItemWidth(-ImGui::GetFontSize() * 9.5f);  // room for the labels
  drawControls(ask);
  drawPresetSection(view, ask, state);
  for (const ParamGroup& group : paramGroups()) {
    const bool open =
        group.name == "Hairstyle" || group.name == "Simulation" || group.name == "Wind";
    if (ImGui::CollapsingHeader(group.name.c_str(), open ? ImGuiTreeNodeFlags_DefaultOpen : 0))
      drawGroupContents(group, view, ask);
  }
  if (ImGui::CollapsingHeader("Messages")) drawMessages(view, 30);
  ImGui::PopItemWidth();
  ImGui::End();
}

void drawBanners(const PanelView& view, PanelRequests& ask, const PanelLayout& layout) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  // Over the hair, between the panels: centred on the part of the window they leave free.
  const float centreX = vp->WorkPos.x + layout.view.x + layout.view.width * 0.5f;
  const ImVec2 topCentre(centreX, vp->WorkPos.y + layout.view.y + 8.0f);
  const float wrap = std::max(200.0f, std::min(vp->WorkSize.x * 0.45f, layout.view.width - 40.0f));
  const ImGuiWindowFlags bannerFlags = ImGuiWindowFlags_NoDecoration |
                                       ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                                       ImGuiWindowFlags_NoSavedSettings |
                                       ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
  float y = topCentre.y;
  auto banner = [&](const char* id, const std::string& text) {
    ImGui::SetNextWindowPos(ImVec2(topCentre.x, y), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.7f, 0.05f, 0.05f, 0.95f));
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 1.0f, 1.0f, 1.0f));
    if (ImGui::Begin(id, nullptr, bannerFlags)) {
      ImGui::PushTextWrapPos(wrap);
      ImGui::TextUnformatted(text.c_str());
      ImGui::PopTextWrapPos();
      y += ImGui::GetWindowHeight() + 6.0f;
    }
    ImGui::End();
    ImGui::PopStyleColor(2);
  };
  if (ask.controls().nanStopped())
    banner("##nan", "The simulation produced NaN at frame " + std::to_string(view.frame.nanFrame) +
                        " (" + std::to_string(view.frame.nanParticles) +
                        " particles) and is paused; strands in the picture may be broken.\n"
                        "Press R to reset the hair to rest, or change the parameters "
                        "(smaller time step, more substeps, less stiffness) or revert the preset.");
  if (const SimThread::ImportStatus import = view.import; !import.stage.empty()) {
    // A long groom import: the window stays live, the old scene on show until it is done.
    ImGui::SetNextWindowPos(ImVec2(topCentre.x, y), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    if (ImGui::Begin("##import", nullptr, bannerFlags)) {
      ImGui::Text("Importing the groom: %s", import.stage.c_str());
      ImGui::ProgressBar(float(import.done), ImVec2(320.0f, 0.0f));
      y += ImGui::GetWindowHeight() + 6.0f;
    }
    ImGui::End();
  }
  if (!view.picture.hasRenderer)
    banner("##renderer", "The renderer did not start, so the hair is simulated but not drawn:\n" +
                             view.picture.rendererError);

  // The latest message, for a few seconds at the bottom: a refused edit or a saved file
  // should not need the Messages section opened to be seen.
  if (!view.messages.empty()) {
    const ViewerMessage& m = view.messages.back();
    const double age =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m.when).count();
    if (age < (m.level == MessageLevel::Info ? 3.0 : 8.0)) {
      // At the bottom of the free part, above the Timeline.
      ImGui::SetNextWindowPos(
          ImVec2(centreX, vp->WorkPos.y + layout.view.y + layout.view.height - 12.0f),
          ImGuiCond_Always, ImVec2(0.5f, 1.0f));
      ImGui::SetNextWindowBgAlpha(0.85f);
      if (ImGui::Begin("##notice", nullptr, bannerFlags)) {
        ImGui::PushTextWrapPos(wrap);
        ImGui::PushStyleColor(ImGuiCol_Text, m.level == MessageLevel::Error ? kRed
                                             : m.level == MessageLevel::Warning
                                                 ? kYellow
                                                 : ImGui::GetStyleColorVec4(ImGuiCol_Text));
        ImGui::TextUnformatted(m.text.c_str());
        ImGui::PopStyleColor();
        ImGui::PopTextWrapPos();
      }
      ImGui::End();
    }
  }

  if (!view.presetErrors.empty()) {
    ImGui::SetNextWindowPos(
        ImVec2(centreX, vp->WorkPos.y + layout.view.y + layout.view.height * 0.3f),
        ImGuiCond_Appearing, ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(std::min(720.0f, vp->WorkSize.x * 0.6f), 0.0f),
                             ImGuiCond_Appearing);
    ImGui::PushStyleColor(ImGuiCol_TitleBg, ImVec4(0.6f, 0.05f, 0.05f, 1.0f));
    ImGui::PushStyleColor(ImGuiCol_TitleBgActive, ImVec4(0.75f, 0.08f, 0.08f, 1.0f));
    const std::string title = "Preset problems: " + view.presetErrorsNote + "###presetproblems";
    if (ImGui::Begin(title.c_str())) {
      ImGui::PushStyleColor(ImGuiCol_Text, kRed);
      for (const std::string& m : view.presetErrors) ImGui::TextWrapped("%s", m.c_str());
      ImGui::PopStyleColor();
      if (ImGui::Button("Dismiss")) ask.dismissPresetErrors();
    }
    ImGui::End();
    ImGui::PopStyleColor(2);
  }
  if (view.picture.shaderReloadFailed) {
    ImGui::SetNextWindowSize(ImVec2(640.0f, 300.0f), ImGuiCond_Appearing);
    if (ImGui::Begin("Shader reload failed: the old shaders are still in use")) {
      if (ImGui::Button("Dismiss")) ask.dismissShaderLog();
      ImGui::SameLine();
      if (ImGui::Button("Try again (F5)")) ask.reloadShaders();
      ImGui::BeginChild("log", ImVec2(0, 0), true, ImGuiWindowFlags_HorizontalScrollbar);
      ImGui::PushStyleColor(ImGuiCol_Text, kRed);
      ImGui::TextUnformatted(view.picture.shaderLog.c_str());
      ImGui::PopStyleColor();
      ImGui::EndChild();
    }
    ImGui::End();
  }
}

PanelLayout panelLayout(float width, float height, float fontSize) {
  // Dear ImGui's default style: a title bar is the font plus 2 x 3 pixels of frame padding, a
  // row of widgets the font plus 10 (padding and item spacing), a row of text the font plus 4;
  // windows are padded by 8 on each side. The widths were chosen for the 15-pixel font.
  const float scale = fontSize / 15.0f;
  const float titleBar = fontSize + 6.0f;
  const float widgetRow = fontSize + 10.0f, textRow = fontSize + 4.0f;
  // The Timeline's six rows of widgets: its slider, play, record and bake, cache, export, A/B.
  const float timeline = std::min(titleBar + 12.0f + 6.0f * widgetRow, 0.35f * height);
  // Parameters as wide as its labels and widgets need (410 at the 15-pixel font), Stats as
  // its lines (380), less on narrow windows. Help's shortcuts (one row each, and a line) need
  // 525 unwrapped: it opens unfolded only where its column can be that wide and has room for
  // it and Stats with every line Stats can show above the Timeline.
  const float left = std::min(410.0f * scale, 0.32f * width);
  const float helpOpen = float(shortcuts().size() + 1) * textRow + titleBar + 20.0f;
  const float statsTall = 32.0f * textRow + titleBar + 16.0f;
  const float column = height - timeline;

  PanelLayout l;
  l.helpOpen = 0.30f * width >= 525.0f * scale && column >= helpOpen + statsTall;
  const float right = std::min(l.helpOpen ? 540.0f * scale : 380.0f * scale, 0.30f * width);
  l.parameters = {0.0f, 0.0f, left, height};
  l.timeline = {left, height - timeline, width - left, timeline};
  l.help = {width - right, 0.0f, right, l.helpOpen ? helpOpen : titleBar};
  l.stats = {width - right, l.help.height, right, std::max(0.0f, column - l.help.height)};
  l.view = {left, 0.0f, std::max(0.0f, width - left - right), column};
  return l;
}

void setNextWindowRect(const PanelRect& r) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + r.x, vp->WorkPos.y + r.y));
  ImGui::SetNextWindowSize(ImVec2(r.width, r.height));
}

void drawPanels(const PanelView& view, PanelRequests& ask, PanelState& state) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const PanelLayout layout = panelLayout(vp->WorkSize.x, vp->WorkSize.y, ImGui::GetFontSize());
  // Laid out on the first frame and again when the window's size changes (a window manager
  // may resize it after it opens), not while it is minimised.
  const bool place = vp->WorkSize.x > 0.0f && vp->WorkSize.y > 0.0f &&
                     (vp->WorkSize.x != state.layoutWidth || vp->WorkSize.y != state.layoutHeight);
  if (place) {
    state.layoutWidth = vp->WorkSize.x;
    state.layoutHeight = vp->WorkSize.y;
  }
  drawParameterPanel(view, ask, state, layout, place);
  if (state.showStats) drawStatsPanel(view, ask, state, layout, place);
  if (state.showTimeline) drawTimelinePanel(view, ask, state, layout, place);
  if (state.showMotion) drawMotionPanel(view, ask, state, layout, place);
  if (state.showHelp) drawHelpPanel(state, layout, place);
  drawBanners(view, ask, layout);
}

}  // namespace csm
