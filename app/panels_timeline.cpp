// The Timeline panel: the simulation thread's recording (sim/run/frame_recording.h) to scrub, play,
// loop, step through and resume from, a bake of seconds with its progress, and the cache's
// memory against its budget.
#include <algorithm>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/panels.h"
#include "app/sim_controls.h"

namespace csm {

void drawTimelinePanel(const PanelView& view, PanelRequests& ask, PanelState& state,
                       const PanelLayout& layout, bool place) {
  // Along the bottom, right of the Parameters panel; its six rows fit its height.
  if (place) setNextWindowRect(layout.timeline);
  if (!ImGui::Begin("Timeline", &state.showTimeline)) {
    ImGui::End();
    return;
  }
  const SimFrame& f = view.frame;
  const TimelineStatus& t = f.timeline;
  const bool recorded = t.first >= 0;
  const long at = t.shown >= 0 ? t.shown : t.live;

  if (recorded) {
    int frame = int(std::clamp(at, t.first, t.last));
    ImGui::SetNextItemWidth(-1.0f);
    std::string label = t.shown < 0                                   ? "live, frame %d"
                        : t.shotFrames > 0 && t.shown <= t.shotFrames ? "cached frame %d"
                                                                      : "recorded frame %d";
    // With a clip, the clip's frame beside the simulation's.
    if (f.clip)
      label +=
          " (clip frame " + std::to_string(f.clip->frameAt(f.time, f.config.motion.loop) + 1) + ")";
    if (ImGui::SliderInt("##frame", &frame, int(t.first), int(t.last), label.c_str())) {
      ask.controls().playRecording(false);
      ask.controls().showRecorded(frame);
    }
  } else {
    ImGui::TextDisabled("nothing recorded yet");
  }
  ImGui::BeginDisabled(!recorded);
  if (ImGui::Button("|<")) {
    ask.controls().playRecording(false);
    ask.controls().showRecorded(t.first);
  }
  ImGui::SameLine();
  if (ImGui::Button("<")) {
    ask.controls().playRecording(false);
    ask.controls().showRecorded(std::max(t.first, at - 1));
  }
  ImGui::SameLine();
  if (ImGui::Button(ask.controls().playingRecording() ? "Stop" : "Play", ImVec2(48.0f, 0.0f)))
    ask.controls().playRecording(!ask.controls().playingRecording());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Play the recording back at real time");
  ImGui::SameLine();
  if (ImGui::Button(">")) {
    ask.controls().playRecording(false);
    ask.controls().showRecorded(std::min(t.last, at + 1));
  }
  ImGui::SameLine();
  if (ImGui::Button(">|")) {
    ask.controls().playRecording(false);
    ask.controls().showRecorded(t.last);
  }
  ImGui::SameLine();
  bool loop = ask.controls().loopRecording();
  if (ImGui::Checkbox("Loop", &loop)) ask.controls().setLoopRecording(loop);
  ImGui::SameLine();
  ImGui::BeginDisabled(t.shown < 0);
  if (ImGui::Button("Resume from here")) ask.controls().resumeFrom(t.shown);
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(
        "Simulate on from the frame shown, with the parameters as they are now.\n"
        "The frames recorded after it are dropped and recorded again.");
  ImGui::SameLine();
  if (ImGui::Button("Live")) ask.controls().showRecorded(-1);
  ImGui::EndDisabled();
  ImGui::EndDisabled();

  bool recording = t.recording;
  if (ImGui::Checkbox("Record", &recording)) ask.controls().setRecording(recording);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90.0f);
  ImGui::InputFloat("s", &state.bakeSeconds, 0.5f, 2.0f, "%.1f");
  state.bakeSeconds = std::clamp(state.bakeSeconds, 0.1f, 600.0f);
  ImGui::SameLine();
  if (ImGui::Button("Bake")) ask.controls().bake(state.bakeSeconds);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Simulate (and record) this many seconds as fast as they go, then pause");
  if (t.bakeLeft > 0 && t.bakeTotal > 0) {
    ImGui::SameLine();
    char text[48];
    std::snprintf(text, sizeof text, "%ld / %ld frames", t.bakeTotal - t.bakeLeft, t.bakeTotal);
    ImGui::ProgressBar(float(t.bakeTotal - t.bakeLeft) / float(t.bakeTotal), ImVec2(-1.0f, 0.0f),
                       text);
  }
  ImGui::SetNextItemWidth(160.0f);
  if (ImGui::SliderInt("cache MB", &state.cacheMb, 16, 8192, "%d MB", ImGuiSliderFlags_Logarithmic))
    ask.controls().setCacheBudget(size_t(state.cacheMb) << 20);
  ImGui::SameLine();
  ImGui::Text("%.1f of %.0f MB, %ld frames (%zu keyframes)", double(t.bytes + t.aBytes) / (1 << 20),
              double(t.budget) / (1 << 20), recorded ? t.last - t.first + 1 : 0L, t.keyframes);
  if (t.shotFrames > 0) {
    ImGui::SameLine();
    ImGui::TextDisabled("(a shot's cache: frames 1-%ld)", t.shotFrames);
  }
  // Out: the recorded range as cyHair files.
  ImGui::BeginDisabled(!recorded);
  if (ImGui::Button("Export .hair"))
    ask.controls().exportRecorded(state.exportDir, t.first, t.last);
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Every recorded frame as FOLDER/frame_00001.hair, ... (cyHair)");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(200.0f);
  ImGui::InputText("folder", state.exportDir, sizeof state.exportDir);
  ImGui::EndDisabled();

  // A/B: the recording kept as A, B simulated again over its span with today's parameters.
  ImGui::BeginDisabled(!recorded);
  if (ImGui::Button("Keep as A")) ask.controls().keepAsA();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Keep this recording, and its parameters, to compare with");
  ImGui::EndDisabled();
  if (t.aFirst >= 0) {
    ImGui::SameLine();
    if (ImGui::Button("Run B")) ask.controls().rerunFromA();
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Simulate A's frames again from its first, with the parameters as they are now:\n"
          "the same head motion and wind, which follow the clock");
    ImGui::SameLine();
    bool a = t.showingA;
    if (ImGui::Checkbox("show A (B)", &a)) ask.controls().showA(a);
    ImGui::SameLine();
    std::string changed;
    for (std::string_view k : ask.controls().keysChangedSinceA())
      changed += (changed.empty() ? "" : ", ") + std::string(k);
    ImGui::Text("A: frames %ld-%ld, %.1f MB; B differs in: %s", t.aFirst, t.aLast,
                double(t.aBytes) / (1 << 20), changed.empty() ? "nothing yet" : changed.c_str());
  }
  if (t.refused > 0)
    ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f),
                       "%ld frames not recorded: one keyframe is larger than the cache", t.refused);
  ImGui::End();
}

}  // namespace csm
