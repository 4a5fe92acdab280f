#include "ui/panels/view_tools.h"

#include <imgui.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "ui/app_state.h"

namespace hdprior::ui {
namespace {

// A left click on the view: released without dragging (a drag orbits or pans).
bool clickedView() {
  const ImGuiIO& io = ImGui::GetIO();
  return !io.WantCaptureMouse && ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[0] < 9.0f;
}

void measureClick(AppState& state) {
  if (!state.cursor) return;
  const Eigen::Vector3d p = state.cursor->city;
  if (!state.measureStart) {
    state.measureStart = p;
    return;
  }
  state.lastMeasure = state.measure(state.measureStart->head<2>(), p.head<2>());
  state.measureStart.reset();
}

}  // namespace

void handleViewTools(AppState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!io.WantCaptureKeyboard) {
    if (ImGui::IsKeyPressed(GLFW_KEY_M, false)) state.measuring = !state.measuring, state.picking = false;
    if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) state.picking = !state.picking, state.measuring = false;
    if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) state.measuring = state.picking = false;
    if (!state.measuring) state.measureStart.reset();
  }
  if (!clickedView()) return;
  if (state.measuring) measureClick(state);
  else if (state.picking && state.cursor) state.lastPick = pickText(state.pick(state.cursor->city.head<2>()));
}

void drawViewTools(AppState& state) {
  if (!state.measuring && !state.picking) return;
  if (ImGui::GetIO().WantCaptureMouse || !state.cursor) return;
  ImGui::BeginTooltip();
  if (state.measuring) {
    ImGui::TextUnformatted(state.measureStart ? "Measure: click the second point" : "Measure: click the first point (Esc: done)");
    if (state.measureStart) {
      const GroundMeasure m = measureGround(*state.measureStart, state.cursor->city, 0.0);
      ImGui::Text("%.2f m", m.distance);
    }
  } else {
    ImGui::TextUnformatted(pickText(state.pick(state.cursor->city.head<2>())).c_str());
  }
  ImGui::EndTooltip();
}

}  // namespace hdprior::ui
