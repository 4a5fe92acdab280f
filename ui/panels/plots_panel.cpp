#include "ui/panels/plots_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ui/app_state.h"
#include "ui/ate_series.h"
#include "ui/panels/panel_layout.h"

namespace hdprior::ui {
namespace {

// The colours of the trajectory layers (file, odometry, optimised), lightened for the dark panel.
ImU32 seriesColor(AteSeries::Kind kind) {
  switch (kind) {
    case AteSeries::Kind::File: return IM_COL32(235, 110, 235, 255);
    case AteSeries::Kind::Odometry: return IM_COL32(255, 150, 60, 255);
    case AteSeries::Kind::Optimized: break;
  }
  return IM_COL32(80, 200, 255, 255);
}

struct PlotArea {
  ImVec2 min, max;
  size_t frames = 1;
  double maxError = 1.0;
  ImVec2 at(size_t frame, double error) const {
    const float x = min.x + (max.x - min.x) * float(frame) / float(std::max<size_t>(1, frames - 1));
    const float y = max.y - (max.y - min.y) * float(std::min(error, maxError) / maxError);
    return {x, y};
  }
};

void drawSeries(ImDrawList* draw, const PlotArea& area, const std::vector<double>& errors, ImU32 color, float thickness) {
  std::vector<ImVec2> line;
  const auto flush = [&] {
    if (line.size() > 1) draw->AddPolyline(line.data(), int(line.size()), color, 0, thickness);
    line.clear();
  };
  for (size_t i = 0; i < errors.size(); ++i) {
    if (std::isfinite(errors[i])) line.push_back(area.at(i, errors[i]));
    else flush();
  }
  flush();
}

double niceCeiling(double v) {
  const double p = std::pow(10.0, std::floor(std::log10(std::max(v, 1e-3))));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (v <= m * p) return m * p;
  return 10.0 * p;
}

void drawAxes(ImDrawList* draw, const PlotArea& area) {
  const ImU32 grid = IM_COL32(255, 255, 255, 40), text = IM_COL32(200, 200, 200, 255);
  for (int i = 0; i <= 5; ++i) {
    const double e = area.maxError * i / 5.0;
    const ImVec2 p = area.at(0, e);
    draw->AddLine(ImVec2(area.min.x, p.y), ImVec2(area.max.x, p.y), grid);
    char label[32];
    std::snprintf(label, sizeof label, area.maxError < 0.1 ? "%.3f" : "%.2f", e);
    draw->AddText(ImVec2(area.min.x - 46, p.y - 7), text, label);
  }
  draw->AddRect(area.min, area.max, IM_COL32(255, 255, 255, 90));
}

}  // namespace

void drawPlotsPanel(AppState& state) {
  const render::Analysis& a = state.bench().analysis();
  const ImGuiIO& io = ImGui::GetIO();
  const float width = io.DisplaySize.x - kLayersPanelWidth - kBenchPanelWidth;
  ImGui::SetNextWindowPos(ImVec2(kLayersPanelWidth, io.DisplaySize.y - kStatusBarHeight - kTimelineHeight - kPlotsHeight),
                          ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, kPlotsHeight), ImGuiCond_Always);
  ImGui::Begin("ATE per frame", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  const std::vector<AteSeries> series = ateSeries(a);
  if (series.empty()) {
    ImGui::TextDisabled("run the pipeline (or open a trajectory file in the Pipeline tab) to see the error of every frame");
    ImGui::End();
    return;
  }
  for (const AteSeries& s : series) {
    ImGui::TextColored(ImColor(seriesColor(s.kind)), "%s", s.label.c_str());
    ImGui::SameLine();
  }
  ImGui::TextDisabled("(translation error, m; click to go to a frame)");
  const ImVec2 origin = ImGui::GetCursorScreenPos(), avail = ImGui::GetContentRegionAvail();
  PlotArea area{ImVec2(origin.x + 48, origin.y + 4), ImVec2(origin.x + avail.x - 6, origin.y + avail.y - 4)};
  area.frames = state.frameCount();
  double maxError = 0.0;
  for (const AteSeries& s : series)
    for (double e : *s.errors)
      if (std::isfinite(e)) maxError = std::max(maxError, e);
  area.maxError = niceCeiling(maxError);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  drawAxes(draw, area);
  // Earlier lines wider: where two coincide (an optimisation that changed little) both stay visible.
  for (size_t i = 0; i < series.size(); ++i)
    drawSeries(draw, area, *series[i].errors, seriesColor(series[i].kind), 1.5f + 1.0f * float(series.size() - 1 - i));
  const ImVec2 cursor = area.at(state.frame().index, 0.0);
  draw->AddLine(ImVec2(cursor.x, area.min.y), ImVec2(cursor.x, area.max.y), IM_COL32(255, 255, 255, 200), 1.0f);

  ImGui::InvisibleButton("plot", avail);
  if (ImGui::IsItemActive() && area.max.x > area.min.x) {
    const float t = std::clamp((io.MousePos.x - area.min.x) / (area.max.x - area.min.x), 0.0f, 1.0f);
    state.goToFrame(std::llround(t * float(area.frames - 1)));
  }
  ImGui::End();
}

}  // namespace hdprior::ui
