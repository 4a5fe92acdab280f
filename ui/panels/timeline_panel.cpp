#include "ui/panels/timeline_panel.h"

#include <imgui.h>

#include <cinttypes>

#include "engine/io/argoverse_log.h"
#include "ui/app_state.h"
#include "ui/panels/panel_layout.h"

namespace hdprior::ui {

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
