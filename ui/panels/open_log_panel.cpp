#include "ui/panels/open_log_panel.h"

#include <imgui.h>

namespace hdprior::ui {

std::optional<std::filesystem::path> drawOpenLogPanel(bool loading, const std::string& error) {
  static char path[1024] = "";
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x / 2, io.DisplaySize.y / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(620, 0));
  ImGui::Begin("Open an Argoverse 2 log", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextWrapped("The log directory (with sensors/lidar, city_SE3_egovehicle.feather, calibration/ and map/):");
  std::optional<std::filesystem::path> chosen;
  if (loading) {
    ImGui::Text("Loading the log and its map %c", "|/-\\"[int(ImGui::GetTime() * 8) % 4]);
  } else {
    ImGui::SetNextItemWidth(-70);
    const bool entered = ImGui::InputText("##dir", path, sizeof path, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("Open") || entered) && path[0] != '\0') chosen = std::filesystem::path(path);
  }
  if (!error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", error.c_str());
  ImGui::End();
  return chosen;
}

}  // namespace hdprior::ui
