#include "ui/panels/timeline_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cinttypes>
#include <vector>

#include "engine/io/argoverse_log.h"
#include "ui/app_state.h"
#include "ui/panels/event_colors.h"
#include "ui/panels/panel_layout.h"

namespace hdprior::ui {
namespace {

// A tick under the frame slider (the last item drawn) at each event's frame, in its kind's colour.
void drawEventTicks(const std::vector<RunEvent>& events, size_t count) {
  if (count < 2 || events.empty()) return;
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  // Where ImGui's slider puts the grab's centre for the first and the last frame.
  const float padding = 2.0f, width = b.x - a.x - 2 * padding;
  const float grab = std::max(width / float(count), ImGui::GetStyle().GrabMinSize);
  const float x0 = a.x + padding + grab / 2, x1 = b.x - padding - grab / 2;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (const RunEvent& e : events) {
    const float x = x0 + (x1 - x0) * float(e.frame) / float(count - 1);
    draw->AddLine(ImVec2(x, b.y - 6), ImVec2(x, b.y - 1), ImGui::GetColorU32(eventColor(e.kind)), 2.0f);
  }
}

}  // namespace

void drawTimelinePanel(AppState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - kStatusBarHeight - kTimelineHeight));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, kTimelineHeight));
  ImGui::Begin("Timeline", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
  const size_t count = state.frameCount();
  const size_t frame = state.frame().index;

  if (ImGui::Button("|<")) state.goToFrame(0);
  ImGui::SameLine();
  if (ImGui::Button("<")) state.step(-1);
  ImGui::SameLine();
  if (ImGui::Button(state.playback.playing ? "Pause" : "Play ", ImVec2(52, 0))) state.playback.toggle();
  ImGui::SameLine();
  if (ImGui::Button(">")) state.step(1);
  ImGui::SameLine();
  if (ImGui::Button(">|")) state.goToFrame((long long)count - 1);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(70);
  ImGui::Combo("speed", &state.playback.speed, Playback::kSpeedNames.data(), int(Playback::kSpeedNames.size()));
  ImGui::SameLine();
  int slider = int(frame);
  ImGui::SetNextItemWidth(-1);
  if (ImGui::SliderInt("##frame", &slider, 0, count > 0 ? int(count) - 1 : 0, "frame %d")) state.goToFrame(slider);
  drawEventTicks(state.bench().analysis().events, count);

  const auto& timestamps = state.log().sweepTimestamps();
  const int64_t ns = state.frame().timestampNs;
  const double seconds = timestamps.empty() ? 0.0 : double(ns - timestamps.front()) * 1e-9;
  ImGui::Text("frame %zu of 0..%zu    t = %.3f s    timestamp %" PRId64 " ns    %s", frame, count > 0 ? count - 1 : 0,
              seconds, ns, state.playback.playing ? "playing" : "paused");
  const char* keys = "Left/Right step   Space play   T top-down   F follow ego";
  ImGui::SameLine(io.DisplaySize.x - ImGui::CalcTextSize(keys).x - 2 * ImGui::GetStyle().WindowPadding.x);
  ImGui::TextDisabled("%s", keys);
  ImGui::End();
}

}  // namespace hdprior::ui
