#include <imgui.h>

#include <string>

#include "ui/app_state.h"
#include "ui/panels/bench_panel.h"

namespace hdprior::ui {
namespace {

ImVec4 eventColor(RunEvent::Kind kind) {
  switch (kind) {
    case RunEvent::Kind::Rejected: return ImVec4(0.95f, 0.35f, 0.3f, 1.0f);
    case RunEvent::Kind::Gated: return ImVec4(1.0f, 0.85f, 0.15f, 1.0f);
    case RunEvent::Kind::ConstraintChange: return ImVec4(0.3f, 0.65f, 1.0f, 1.0f);
    case RunEvent::Kind::Beyond3Sigma: return ImVec4(1.0f, 0.5f, 0.9f, 1.0f);
    case RunEvent::Kind::MapChange: return ImVec4(1.0f, 0.3f, 1.0f, 1.0f);
    case RunEvent::Kind::MissedChange: return ImVec4(0.1f, 0.95f, 0.95f, 1.0f);  // the changes layer's labelled cyan
    case RunEvent::Kind::MisalignedSweeps: return ImVec4(1.0f, 0.6f, 0.2f, 1.0f);
    case RunEvent::Kind::SkippedSweep: break;
  }
  return ImVec4(0.7f, 0.7f, 0.7f, 1.0f);
}

void drawEvents(AppState& state) {
  const std::vector<RunEvent>& events = state.bench().analysis().events;
  ImGui::Text("%zu events", events.size());
  ImGui::SameLine();
  ImGui::TextDisabled("(N / Shift+N: next / previous)");
  ImGui::BeginChild("events", ImVec2(0, 260), true);
  for (size_t i = 0; i < events.size(); ++i) {
    const RunEvent& e = events[i];
    const std::string label = "frame " + std::to_string(e.frame) + "  " + toString(e.kind) + "  " + e.detail + "##" + std::to_string(i);
    ImGui::PushStyleColor(ImGuiCol_Text, eventColor(e.kind));
    if (ImGui::Selectable(label.c_str(), state.currentEvent == i)) {
      state.currentEvent = i;
      if (isFrameEvent(e.kind)) state.goToFrame((long long)e.frame);
      else state.inspectKeyframe(e.keyframe);
    }
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.detail.c_str());  // the panel is narrower than most details
    if (state.scrollToEvent && state.currentEvent == i) {
      ImGui::SetScrollHereY(0.5f);
      state.scrollToEvent = false;
    }
  }
  ImGui::EndChild();
}

void drawBookmarks(AppState& state) {
  ImGui::Text("%zu bookmarks", state.bookmarks.size());
  ImGui::SameLine();
  if (ImGui::SmallButton("add (B)")) state.addBookmark("");
  for (size_t i = 0; i < state.bookmarks.size(); ++i) {
    Bookmark& b = state.bookmarks[i];
    ImGui::PushID(int(i));
    if (ImGui::SmallButton(("frame " + std::to_string(b.frame)).c_str())) state.goToFrame((long long)b.frame);
    ImGui::SameLine();
    char note[256];
    std::snprintf(note, sizeof note, "%s", b.note.c_str());
    ImGui::SetNextItemWidth(-1);
    if (ImGui::InputTextWithHint("##note", "note", note, sizeof note)) b.note = note;
    ImGui::PopID();
  }
}

}  // namespace

void drawEventsTab(AppState& state) {
  drawEvents(state);
  ImGui::Separator();
  drawBookmarks(state);
}

}  // namespace hdprior::ui
