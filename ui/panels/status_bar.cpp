#include "ui/panels/status_bar.h"

#include <imgui.h>

#include <cmath>
#include <numbers>

#include "ui/app_state.h"
#include "ui/panels/panel_layout.h"

namespace hdprior::ui {

void drawStatusBar(AppState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y - kStatusBarHeight));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, kStatusBarHeight));
  ImGui::Begin("Status", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
  const Eigen::Vector3d t = state.frame().cityTEgo.translation();
  const Eigen::Vector3d forward = state.frame().cityTEgo.linear().col(0);
  const double yawDeg = std::atan2(forward.y(), forward.x()) * 180.0 / std::numbers::pi;
  ImGui::Text("%5.1f FPS  |  %zu points  |  ego x %.2f  y %.2f  z %.2f  yaw %.1f deg", io.Framerate,
              state.renderer().pointsDrawn(), t.x(), t.y(), t.z(), yawDeg);
  ImGui::SameLine();
  if (state.error) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "  |  %s", state.error->what());
    ImGui::End();
    return;
  }
  if (state.measuring || state.picking) ImGui::Text("  |  %s", state.measuring ? "MEASURE" : "PICK");
  if (state.lastMeasure && state.measuring) {
    const GroundMeasure& m = *state.lastMeasure;
    ImGui::SameLine();
    ImGui::Text("  %.3f m: along %.3f, across %.3f, rise %.3f", m.distance, m.along, m.lateral, m.rise);
    ImGui::End();
    return;
  }
  if (!state.lastPick.empty() && state.picking) {
    ImGui::SameLine();
    ImGui::TextUnformatted(state.lastPick.c_str());
    ImGui::End();
    return;
  }
  ImGui::SameLine();
  if (state.cursor) {
    const GroundCursor& c = *state.cursor;
    if (std::isfinite(c.groundHeight))
      ImGui::Text("  |  cursor x %.2f  y %.2f  ground %.2f m", c.city.x(), c.city.y(), c.groundHeight);
    else
      ImGui::Text("  |  cursor x %.2f  y %.2f  ground: no data", c.city.x(), c.city.y());
  } else {
    ImGui::TextDisabled("  |  cursor: not over the ground");
  }
  ImGui::End();
}

}  // namespace hdprior::ui
