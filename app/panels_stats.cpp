// The Stats and Help panels.
#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <string>

#include <imgui.h>

#include "app/metrics.h"
#include "app/panels.h"
#include "app/sim_controls.h"

namespace csm {
namespace {

void stageRows(const char* what, const std::vector<StageTime>& stages) {
  for (const StageTime& s : stages) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::Text("%s %s", what, s.name.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%7.2f ms", s.ms);
  }
}

// A fixed width: the panel sizes itself to its contents, so "fill the width" would be 0.
void plot(const char* id, const History& h, const char* overlay, float floor) {
  const float top = std::max(floor, h.max() * 1.15f);
  ImGui::PlotLines(id, h.values(), h.size(), h.offset(), overlay, 0.0f, top,
                   ImVec2(ImGui::GetFontSize() * 22.0f, ImGui::GetFontSize() * 3.5f));
}

// A count of what went wrong, in the warning colour, with a tooltip saying more (none when
// `tooltip` is null). `format` takes the count.
void warning(const char* format, unsigned long long count, const char* tooltip) {
  ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.3f, 1.0f), format, count);
  if (tooltip && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
}

}  // namespace

const std::vector<Shortcut>& shortcuts() {
  static const std::vector<Shortcut> list = {
      {"Space", "pause / run"},
      {"N or .", "step one frame (pauses)"},
      {"R", "reset the hair to rest"},
      {"F12 or P", "screenshot (csmhair_<time>.png, panels included)"},
      {"F", "frame the head"},
      {"Home", "reset the view to the preset's camera"},
      {"G", "undo the head drag"},
      {"F5", "reload shaders from disk"},
      {"Ctrl+S", "save the preset"},
      {"F1", "show / hide this help"},
      {"Left drag", "orbit the camera"},
      {"Shift+left or middle drag", "pan"},
      {"Wheel", "zoom"},
      {"Right or Ctrl+left drag", "turn the head about the neck"},
  };
  return list;
}

void drawStatsPanel(const PanelView& view, PanelRequests& ask, PanelState& state,
                    const PanelLayout& layout, bool place) {
  // As tall as its lines, up to its place above the Timeline (then it scrolls), and as wide as
  // its column: lines longer than that scroll sideways.
  if (place) setNextWindowRect(layout.stats);
  ImGui::SetNextWindowSizeConstraints(ImVec2(layout.stats.width, 0.0f),
                                      ImVec2(layout.stats.width, layout.stats.height));
  if (!ImGui::Begin("Stats", &state.showStats,
                    ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_HorizontalScrollbar)) {
    ImGui::End();
    return;
  }
  const ViewerStats& s = view.stats;
  const SimFrame& f = view.frame;
  ImGui::Text("%.1f fps   %.1f ms a frame", s.fps, s.frameMs.mean());
  ImGui::Text("solver %s, %s", solverLabel(f).c_str(), view.renderer.c_str());
  ImGui::Text("t = %.2f s, frame %ld%s", f.time, f.frame,
              view.loading              ? "  (loading)"
              : ask.controls().paused() ? "  (paused)"
                                        : "");
  ImGui::Text("timeline: %.1f of %.0f MB, %ld frames%s",
              double(f.timeline.bytes + f.timeline.aBytes) / (1 << 20),
              double(f.timeline.budget) / (1 << 20),
              f.timeline.first >= 0 ? f.timeline.last - f.timeline.first + 1 : 0L,
              f.timeline.shown >= 0 ? ", one shown" : "");
  if (view.picture.lastQuality == DrawQuality::Interactive)
    ImGui::TextDisabled("picture: interactive quality, %.0f %% of children and followers",
                        100.0 * double(view.picture.interactiveExtra));
  else
    ImGui::TextDisabled("picture: full quality");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "While the camera moves or the hair simulates the scene is drawn with\n"
        "Rendering > Interactive's settings, as many children and followers as the\n"
        "frame budget allows (measured); when still, and for screenshots, in full.");

  char overlay[96];
  std::snprintf(overlay, sizeof overlay, "UI frame time, ms (max %.1f)", s.frameMs.max());
  plot("##frame", s.frameMs, overlay, 1.0f);
  std::snprintf(overlay, sizeof overlay, "max strain (now %.4f)", f.maxStrain.latest());
  plot("##strain", f.maxStrain, overlay, 0.01f);
  ImGui::TextDisabled("strain and NaN: sampled each frame, a few frames late");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "The solver reduces each frame's state to a few numbers on the GPU and copies them\n"
        "behind a fence; they are read when ready, so nothing waits for the GPU.");

  if (ImGui::BeginTable("stages", 2, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("simulation step (wall)");
    ImGui::TableNextColumn();
    ImGui::Text("%7.2f ms", f.stepMs);
    stageRows("sim", f.stages);
    stageRows("render", s.renderStages);
    ImGui::EndTable();
  }
  ImGui::Separator();
  const FrameSample sample = f.sample.value_or(FrameSample{});
  const ContactStats& contacts = sample.contacts;
  if (!sample.contactsMeasured) {
    ImGui::TextDisabled("hair contacts: not measured (hair-hair off)");
  } else {
    ImGui::Text("hair contacts %llu, closer than r %llu", (unsigned long long)contacts.contacts,
                (unsigned long long)contacts.penetrations);
    // The measures of the candidate list the sampled frame started from.
    ImGui::Text("crossings %llu (%.0f/s; %llu close at rest), candidates %llu",
                (unsigned long long)contacts.crossings,
                double(contacts.crossings) / std::max(1e-6, double(f.config.sim.dt)),
                (unsigned long long)contacts.crossingsClose,
                (unsigned long long)contacts.candidates);
    ImGui::Text("penetration depth p50 %.2f r, p99 %.2f r, max %.2f r", contacts.depthQuantile(0.5),
                contacts.depthQuantile(0.99), double(contacts.maxDepth));
    // A large hair without strand contacts is measured on a sample of its strands.
    if (contacts.measureStride > 1)
      ImGui::TextDisabled("measured on 1 strand in %u: counts of the sample's pairs",
                          unsigned(contacts.measureStride));
    // Never silent: what the GPU's lists could not hold.
    if (contacts.overflows > 0)
      warning("hair-hair lists full in %llu frames (the list before kept there)",
              contacts.overflows,
              "A frame whose candidate pairs do not fit the GPU's buffers keeps the list before\n"
              "it (its pairs, evaluated where the hair is now; none after a reset or a growth)\n"
              "and counts no crossings; the buffers grow to what it needed as the next frame\n"
              "begins (up to collision.contact_memory_mb, and what the device's buffer\n"
              "textures hold: 134 M pairs on llvmpipe and NVIDIA), so the frames after it\n"
              "fit. Counted since the\n"
              "simulation was last reset.");
    if (contacts.oversize > 0)
      warning("%llu segments too long for the grid's cells: no contacts for them",
              contacts.oversize, nullptr);
    if (contacts.crowded > 0)
      warning("%llu segments in a crowd: some or all of their contacts missing", contacts.crowded,
              "More than 2,048 candidate pairs for one segment (it is then in no pair this\n"
              "frame), or a grid cell so full that the driver cut the search short. Hair does\n"
              "not pack that densely: the strands are too many for this collision radius, or\n"
              "the simulation is exploding.");
  }
  if (f.carriedFrames > 0)
    warning("head jumps: %llu frames carried the hair with the head",
            (unsigned long long)f.carriedFrames,
            "In these frames (since the last reset) the head moved its roots faster than\n"
            "2 m/s (a reset of the drag, a fast drag): the hair went with it, rigidly, for the\n"
            "part of the move beyond that speed instead of being flung.");
  ImGui::Text("penetrations: head %llu, torso %llu; max speed %.2f m/s",
              (unsigned long long)sample.accuracy.headPenetrations,
              (unsigned long long)sample.accuracy.torsoPenetrations, sample.accuracy.maxSpeed);
  ImGui::Text("particles %zu", f.particles);
  if (f.drawnStrands > f.strands)
    ImGui::Text("strands simulated %zu (guides of %zu), drawn %zu", f.strands, f.drawnStrands,
                s.drawnStrands);
  else
    ImGui::Text("strands simulated %zu, drawn %zu", f.strands, s.drawnStrands);
  // What the scene takes: the solver's buffers by kind (on llvmpipe, process memory) and the
  // process's peak.
  constexpr double kMiB = 1024.0 * 1024.0;
  if (const uint64_t bytes = f.memory.total(); bytes > 0) {
    ImGui::Text("solver buffers %.1f MiB (%.0f B a particle)", double(bytes) / kMiB,
                f.particles > 0 ? double(bytes) / double(f.particles) : 0.0);
    if (ImGui::IsItemHovered()) {
      std::string kinds;
      for (const auto& [kind, b] : f.memory.bytes) {
        char line[96];
        std::snprintf(line, sizeof line, "%s%s %.2f MiB", kinds.empty() ? "" : "\n", kind.c_str(),
                      double(b) / kMiB);
        kinds += line;
      }
      ImGui::SetTooltip("%s", kinds.c_str());
    }
  }
  ImGui::Text("peak memory %.0f MiB (resident)", double(peakResidentBytes()) / kMiB);
  const GroomReport& groom = f.groomReport;
  if (groom.fileStrands > 0) {
    ImGui::Text("groom file: %zu strands; resampling saved %zu of %zu points", groom.fileStrands,
                groom.savedPoints(), groom.filePoints);
    if (const std::string repairs = groomReportText(groom); !repairs.empty()) {
      // The summary line; the notes (with their bytes or lines) as a tooltip.
      const std::string summary = repairs.substr(0, repairs.find('\n'));
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "%s", summary.c_str());
      ImGui::PopTextWrapPos();
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", repairs.c_str());
    }
  }
  bool vsync = view.vsync;
  if (ImGui::Checkbox("vsync", &vsync)) ask.setVsync(vsync);
  ImGui::End();
}

void drawHelpPanel(PanelState& state, const PanelLayout& layout, bool place) {
  // Above Stats, as wide as their column (the actions wrap to it); folded to its title bar
  // unless the window has room for it and Stats both, so that it covers nothing.
  if (place) {
    setNextWindowRect(layout.help);
    ImGui::SetNextWindowCollapsed(!layout.helpOpen, ImGuiCond_Always);
  }
  ImGui::SetNextWindowSizeConstraints(ImVec2(layout.help.width, 0.0f),
                                      ImVec2(layout.help.width, FLT_MAX));
  if (!ImGui::Begin("Help (F1)", &state.showHelp, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingFixedFit)) {
    ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
    for (const Shortcut& k : shortcuts()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(k.keys);
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", k.action);
    }
    ImGui::EndTable();
  }
  ImGui::TextDisabled("Hover a parameter for what it does.");
  ImGui::End();
}

}  // namespace csm
