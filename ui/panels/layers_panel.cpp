#include "ui/panels/layers_panel.h"

#include <imgui.h>

#include <vector>

#include "engine/io/argoverse_log.h"
#include "render/layer.h"
#include "ui/app_state.h"
#include "ui/panels/panel_layout.h"

namespace hdprior::ui {
namespace {

// Draws one option; true when it changed.
bool drawOption(const render::LayerOption& option) {
  using Kind = render::LayerOption::Kind;
  switch (option.kind) {
    case Kind::Slider: return ImGui::SliderFloat(option.label.c_str(), option.real, option.min, option.max, "%.1f");
    case Kind::IntSlider:
      return ImGui::SliderInt(option.label.c_str(), option.integer, int(option.min), int(option.max));
    case Kind::Choice: {
      std::vector<const char*> items;
      for (const auto& c : option.choices) items.push_back(c.c_str());
      return ImGui::Combo(option.label.c_str(), option.integer, items.data(), int(items.size()));
    }
    case Kind::Color: return ImGui::ColorEdit4(option.label.c_str(), option.color->data(), ImGuiColorEditFlags_NoInputs);
  }
  return false;
}

void drawLayer(AppState& state, render::Layer& layer) {
  ImGui::PushID(&layer);
  bool visible = layer.visible;
  if (ImGui::Checkbox("##visible", &visible)) state.setLayerVisible(layer, visible);
  ImGui::SameLine();
  if (ImGui::TreeNode(layer.name().c_str())) {
    ImGui::SetNextItemWidth(140);
    ImGui::SliderFloat("opacity", &layer.opacity, 0.0f, 1.0f, "%.2f");
    for (const render::LayerOption& option : layer.options()) {
      ImGui::SetNextItemWidth(140);
      if (drawOption(option) && option.rebuilds) state.renderer().rebuild(layer);
    }
    ImGui::TreePop();
  }
  ImGui::PopID();
}

void drawCameraControls(AppState& state) {
  ViewCamera& camera = state.camera;
  if (ImGui::RadioButton("orbit", !camera.topDown)) camera.topDown = false;
  ImGui::SameLine();
  if (ImGui::RadioButton("top-down", camera.topDown)) camera.topDown = true;
  ImGui::SameLine();
  if (ImGui::Checkbox("follow ego", &camera.followEgo))
    camera.follow(state.frame().cityTEgo.translation() - state.scene().origin);
  ImGui::TextDisabled("drag: orbit (top-down: pan)\nright/middle drag or shift: pan\nwheel, +/-: zoom  Q/E: turn\nW/A/S/D: move  R: reset");
}

}  // namespace

void drawLayersPanel(AppState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(kLayersPanelWidth, io.DisplaySize.y - kTimelineHeight - kStatusBarHeight));
  ImGui::SetNextWindowBgAlpha(0.82f);
  ImGui::Begin("Layers", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::TextDisabled("%s", state.log().id().c_str());
  ImGui::TextDisabled("city %s, %zu sweeps", state.log().city().c_str(), state.frameCount());
  ImGui::Separator();
  // Top of the list is drawn on top: the reverse of the drawing order.
  const auto& layers = state.renderer().layers();
  for (auto it = layers.rbegin(); it != layers.rend(); ++it) drawLayer(state, **it);
  ImGui::Separator();
  ImGui::Text("Camera");
  drawCameraControls(state);
  ImGui::End();
}

}  // namespace hdprior::ui
