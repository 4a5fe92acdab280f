#include "ui/panels/height_legend.h"

#include <imgui.h>

#include <cstdio>
#include <functional>

#include "render/colormap.h"
#include "render/layers/sweep_coloring.h"
#include "ui/app_state.h"
#include "ui/panels/panel_layout.h"

namespace hdprior::ui {
namespace {

ImU32 packed(const Eigen::Vector3f& c) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.x(), c.y(), c.z(), 1.0f)); }

// A horizontal bar of the colour map with its two end labels under it.
void colorBar(const std::function<Eigen::Vector3f(float)>& map, const char* low, const char* high) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x, height = 12.0f;
  constexpr int kSteps = 32;
  for (int i = 0; i < kSteps; ++i) {
    const float x0 = origin.x + width * i / kSteps, x1 = origin.x + width * (i + 1) / kSteps;
    const ImU32 a = packed(map(float(i) / kSteps)), b = packed(map(float(i + 1) / kSteps));
    draw->AddRectFilledMultiColor(ImVec2(x0, origin.y), ImVec2(x1, origin.y + height), a, b, b, a);
  }
  ImGui::Dummy(ImVec2(width, height));
  ImGui::TextUnformatted(low);
  ImGui::SameLine(width - ImGui::CalcTextSize(high).x + ImGui::GetStyle().WindowPadding.x);
  ImGui::TextUnformatted(high);
}

// The colouring chosen in the sweep layer's options.
render::SweepColoring sweepColoring(AppState& state) {
  if (render::Layer* sweep = state.layer("sweep"))
    for (const render::LayerOption& option : sweep->options())
      if (option.kind == render::LayerOption::Kind::Choice && option.label == "colour by")
        return render::SweepColoring(*option.integer);
  return render::SweepColoring::Height;
}

}  // namespace

void drawHeightLegend(AppState& state) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - kBenchPanelWidth - kLegendWidth - 8, 8));
  ImGui::SetNextWindowSize(ImVec2(kLegendWidth, 0));
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin("Legend", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_AlwaysAutoResize);
  if (const auto& range = state.groundColorRange()) {
    ImGui::Text("ground height (city z)");
    char low[32], high[32];
    std::snprintf(low, sizeof low, "%.1f m", range->low);
    std::snprintf(high, sizeof high, "%.1f m", range->high);
    colorBar(render::terrain, low, high);
  }
  switch (sweepColoring(state)) {
    case render::SweepColoring::Height: {
      ImGui::Text("sweep: height above ground");
      char low[32], high[32];
      std::snprintf(low, sizeof low, "%.1f m", render::kSweepHeightLow);
      std::snprintf(high, sizeof high, "%.1f m", render::kSweepHeightHigh);
      colorBar(render::turbo, low, high);
      break;
    }
    case render::SweepColoring::Intensity: {
      ImGui::Text("sweep: intensity");
      char high[32];
      std::snprintf(high, sizeof high, ">= %.0f", render::kSweepIntensityHigh);
      colorBar(render::turbo, "0", high);
      break;
    }
    case render::SweepColoring::LaserNumber: ImGui::Text("sweep: laser number (one colour per ring)"); break;
  }
  ImGui::End();
}

}  // namespace hdprior::ui
