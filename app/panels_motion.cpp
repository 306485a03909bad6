// The Motion panel: a motion clip opened (motion.clip), what was inferred of it (units, up axis,
// facing, its head and chest joints, travel, cuts), its joints, and the clip's frame on show with
// a slider over its frames that scrubs the timeline's recording; loop and in place; a button that
// records the whole clip, to scrub and play it back.
#include <algorithm>
#include <cmath>
#include <string>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "app/panels.h"
#include "app/sim_controls.h"

namespace csm {
namespace {

// Sets one parameter of the edited preset and applies it.
void applyParam(PanelRequests& ask, std::string_view key, const std::string& text) {
  Preset next = ask.editedPreset();
  const PresetParam* p = findParam(key);
  if (!p || !paramFromText(*p, next, text).empty()) return;
  ask.applyConfig(next);
}

void drawJoints(const ClipFacts& f) {
  if (!ImGui::TreeNode("joints", "%d joints", f.joints)) return;
  for (size_t i = 0; i < f.jointNames.size(); ++i) {
    int depth = 0;
    for (int p = f.jointParents[i]; p >= 0 && depth < 64; p = f.jointParents[size_t(p)]) ++depth;
    const bool drives = f.jointNames[i] == f.headJoint || f.jointNames[i] == f.chestJoint;
    ImGui::Indent(float(depth) * 8.0f);
    if (drives)
      ImGui::TextColored(ImVec4(0.5f, 0.9f, 1.0f, 1.0f), "%s (%s)", f.jointNames[i].c_str(),
                         f.jointNames[i] == f.headJoint ? "head" : "torso");
    else
      ImGui::TextUnformatted(f.jointNames[i].c_str());
    ImGui::Unindent(float(depth) * 8.0f);
  }
  ImGui::TreePop();
}

}  // namespace

void drawMotionPanel(const PanelView& view, PanelRequests& ask, PanelState& state,
                     const PanelLayout& layout, bool place) {
  if (place) {
    // At the top of the view, left: over the hair's space, folded to its title until asked.
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + layout.view.x + 8.0f, vp->WorkPos.y + 8.0f));
    ImGui::SetNextWindowSize(ImVec2(std::min(440.0f, layout.view.width - 16.0f), 0.0f));
    ImGui::SetNextWindowCollapsed(!view.frame.clip, ImGuiCond_Always);
  }
  if (!ImGui::Begin("Motion", &state.showMotion)) {
    ImGui::End();
    return;
  }
  const SimFrame& frame = view.frame;
  const Config& config = frame.config;
  if (state.clipPath.empty()) state.clipPath = config.motion.clip;
  ImGui::SetNextItemWidth(-120.0f);
  ImGui::InputText("##clip", &state.clipPath);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("A BVH clip's path (relative to the preset)");
  ImGui::SameLine();
  if (ImGui::Button("Open")) applyParam(ask, "motion.clip", state.clipPath);
  ImGui::SameLine();
  ImGui::BeginDisabled(config.motion.clip.empty());
  if (ImGui::Button("None")) {
    state.clipPath.clear();
    applyParam(ask, "motion.clip", "");
  }
  ImGui::EndDisabled();

  const MotionClip* clip = frame.clip.get();
  if (!clip) {
    ImGui::TextDisabled("no clip: head.motion (%s) moves the head",
                        config.motion.clip.empty() ? "the preset's" : "the clip did not open");
    ImGui::End();
    return;
  }
  const ClipFacts& f = clip->facts();
  ImGui::Text("%d frames at %.1f fps, %.2f s", f.frames, 1.0 / f.frameTime, clip->duration());
  if (f.unit == "set")
    ImGui::Text("%.6g m a unit (set)", f.scale);
  else
    ImGui::Text("%s (inferred: a skeleton %.2f m tall)", f.unit.c_str(), f.height);
  ImGui::Text("%c up%s, facing %s%s", f.up, f.upSaid ? "" : " (inferred)", f.facing.c_str(),
              f.facingSaid ? "" : " (inferred)");
  ImGui::Text("head joint %s, chest joint %s", f.headJoint.c_str(), f.chestJoint.c_str());
  ImGui::Text("travel %.2f m, the head up to %.2f m/s", f.travel, f.peakHeadSpeed);
  if (!f.cuts.empty())
    ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f),
                       "%zu cuts (the first at clip frame %d): the hair is carried over each; "
                       "%ld so far",
                       f.cuts.size(), f.cuts.front() + 1, frame.clipCuts);
  drawJoints(f);

  // The clip's frame on show, and its frames over the recording.
  const double dt = double(config.sim.dt);
  const bool loop = config.motion.loop;
  const int shown = clip->frameAt(frame.time, loop);
  const TimelineStatus& t = frame.timeline;
  const bool recorded = t.first >= 0;
  int pick = shown + 1;
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::BeginDisabled(!recorded);
  if (ImGui::SliderInt("##clipframe", &pick, 1, f.frames, "clip frame %d")) {
    // The first simulated frame at or after that clip frame, within the recording.
    const long simFrame = long(std::ceil((pick - 1) * clip->frameTime() / dt - 1e-9));
    ask.controls().playRecording(false);
    ask.controls().showRecorded(std::clamp(std::max(simFrame, 1L), t.first, t.last));
  }
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Scrubs the recording (the Timeline) by the clip's frames");
  ImGui::Text("frame %ld, %.2f s: clip frame %d of %d", frame.frame, frame.time, shown + 1,
              f.frames);
  for (const char* key : {"motion.loop", "motion.in_place"}) {
    if (const PresetParam* p = findParam(key)) {
      if (paramWidget(*p, ask.editedPreset()) == ParamEdit::Apply)
        ask.applyConfig(Preset(ask.editedPreset()));
      ImGui::SameLine();
    }
  }
  if (ImGui::Button("Record the clip")) {
    ask.controls().resetHair();
    ask.controls().bake(clip->duration() + dt);
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "From its first frame: the whole clip simulated and recorded, to scrub and play");
  ImGui::End();
}

}  // namespace csm
