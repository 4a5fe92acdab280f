#include "ui/camera_input.h"

#include <imgui.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "ui/app_state.h"

namespace hdprior::ui {
namespace {

void handleMouse(AppState& state, float viewportHeight) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureMouse) return;
  ViewCamera& camera = state.camera;
  const ImVec2 d = io.MouseDelta;
  const bool panDrag = ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f) ||
                       ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0.0f) ||
                       (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f) && (io.KeyShift || camera.topDown));
  if (panDrag)
    camera.pan(d.x, d.y, viewportHeight);
  else if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f))
    camera.orbit(d.x, d.y);
  if (io.MouseWheel != 0.0f) camera.zoom(io.MouseWheel);
}

void handleKeys(AppState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return;
  ViewCamera& camera = state.camera;
  if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT, true)) state.step(1);
  if (ImGui::IsKeyPressed(GLFW_KEY_LEFT, true)) state.step(-1);
  if (ImGui::IsKeyPressed(GLFW_KEY_HOME, false)) state.goToFrame(0);
  if (ImGui::IsKeyPressed(GLFW_KEY_END, false)) state.goToFrame((long long)state.frameCount() - 1);
  if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) state.playback.toggle();
  if (ImGui::IsKeyPressed(GLFW_KEY_T, false)) camera.topDown = !camera.topDown;
  if (ImGui::IsKeyPressed(GLFW_KEY_N, false)) state.goToEvent(io.KeyShift ? -1 : 1);
  if (ImGui::IsKeyPressed(GLFW_KEY_B, false)) {
    state.addBookmark("");
    state.selectTab = "Events";
  }
  const Eigen::Vector3d ego = state.frame().cityTEgo.translation() - state.scene().origin;
  if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) {
    camera.followEgo = !camera.followEgo;
    camera.follow(ego);
  }
  if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) {
    const ViewCamera fresh;
    camera.pitch = fresh.pitch;
    camera.distance = fresh.distance;
    camera.topHeight = fresh.topHeight;
    camera.followEgo = true;
    camera.follow(ego);
  }
  // Held keys move continuously, at a rate independent of the frame rate.
  const double step = 400.0 * io.DeltaTime;  // pixels of equivalent drag per second
  if (ImGui::IsKeyDown(GLFW_KEY_W)) camera.pan(0, step, 720);
  if (ImGui::IsKeyDown(GLFW_KEY_S)) camera.pan(0, -step, 720);
  if (ImGui::IsKeyDown(GLFW_KEY_A)) camera.pan(step, 0, 720);
  if (ImGui::IsKeyDown(GLFW_KEY_D)) camera.pan(-step, 0, 720);
  if (ImGui::IsKeyDown(GLFW_KEY_Q)) camera.orbit(-step, 0);
  if (ImGui::IsKeyDown(GLFW_KEY_E)) camera.orbit(step, 0);
  if (ImGui::IsKeyDown(GLFW_KEY_EQUAL) || ImGui::IsKeyDown(GLFW_KEY_KP_ADD)) camera.zoom(4.0 * io.DeltaTime);
  if (ImGui::IsKeyDown(GLFW_KEY_MINUS) || ImGui::IsKeyDown(GLFW_KEY_KP_SUBTRACT)) camera.zoom(-4.0 * io.DeltaTime);
}

}  // namespace

void handleViewInput(AppState& state, float viewportHeight) {
  handleMouse(state, viewportHeight);
  handleKeys(state);
}

}  // namespace hdprior::ui
