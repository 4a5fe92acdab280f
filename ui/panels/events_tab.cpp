#include <imgui.h>

#include <string>

#include "ui/app_state.h"
#include "ui/panels/bench_panel.h"
#include "ui/panels/event_colors.h"

namespace hdprior::ui {
namespace {

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
