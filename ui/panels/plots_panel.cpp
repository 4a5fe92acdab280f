#include "ui/panels/plots_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/eval/axis_ticks.h"
#include "ui/app_state.h"
#include "ui/ate_series.h"
#include "ui/panels/diagnostic_plot_view.h"
#include "ui/panels/panel_layout.h"
#include "ui/panels/plot_area.h"

namespace hdprior::ui {
namespace {

// The colours of the trajectory layers (file, odometry, optimised), lightened for the dark panel.
ImU32 seriesColor(AteSeries::Kind kind) {
  switch (kind) {
    case AteSeries::Kind::File: return IM_COL32(235, 110, 235, 255);
    case AteSeries::Kind::Odometry: return IM_COL32(255, 150, 60, 255);
    case AteSeries::Kind::Comparison: return IM_COL32(77, 255, 191, 255);
    case AteSeries::Kind::Optimized: break;
  }
  return IM_COL32(80, 200, 255, 255);
}

void drawSeries(ImDrawList* draw, const PlotArea& area, const std::vector<double>& errors, ImU32 color, float thickness) {
  std::vector<ImVec2> line;
  const auto flush = [&] {
    if (line.size() > 1) draw->AddPolyline(line.data(), int(line.size()), color, 0, thickness);
    line.clear();
  };
  for (size_t i = 0; i < errors.size(); ++i) {
    if (std::isfinite(errors[i])) line.push_back(area.at(double(i), errors[i]));
    else flush();
  }
  flush();
}

void drawAxes(ImDrawList* draw, const PlotArea& area) {
  const ImU32 grid = IM_COL32(255, 255, 255, 40), text = IM_COL32(200, 200, 200, 255);
  const AxisTicks ticks = axisTicks(0.0, area.high, 5);
  for (int k = 0; k <= ticks.count() && ticks.at(k) <= area.high * (1.0 + 1e-9); ++k) {
    const float y = area.yOf(ticks.at(k));
    draw->AddLine(ImVec2(area.min.x, y), ImVec2(area.max.x, y), grid);
    draw->AddText(ImVec2(area.min.x - 46, y - 7), text, tickLabel(ticks.at(k), ticks.decimals).c_str());
  }
  draw->AddRect(area.min, area.max, IM_COL32(255, 255, 255, 90));
}

// The "plots" menu: which Diagnostics plots show.
void drawPlotMenu(AppState& state) {
  if (ImGui::SmallButton("plots...")) ImGui::OpenPopup("diagnostic plots");
  if (!ImGui::BeginPopup("diagnostic plots")) return;
  for (const DiagnosticPlot& p : diagnosticPlots()) {
    bool shown = state.plotShown(p.name);
    if (ImGui::Checkbox(p.name, &shown)) state.setPlotShown(p.name, shown);
    ImGui::SameLine(130);
    ImGui::TextDisabled("%s", p.title);
  }
  ImGui::EndPopup();
}

void drawAtePlot(AppState& state, const std::vector<AteSeries>& series, ImVec2 origin, ImVec2 size) {
  PlotArea area{ImVec2(origin.x + 48, origin.y + 4), ImVec2(origin.x + size.x - 6, origin.y + size.y - 4)};
  area.frames = state.frameCount();
  double maxError = 0.0;
  for (const AteSeries& s : series)
    for (double e : *s.errors)
      if (std::isfinite(e)) maxError = std::max(maxError, e);
  area.high = niceCeiling(maxError);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  drawAxes(draw, area);
  // Earlier lines wider: where two coincide (an optimisation that changed little) both stay visible.
  for (size_t i = 0; i < series.size(); ++i)
    drawSeries(draw, area, *series[i].errors, seriesColor(series[i].kind), 1.5f + 1.0f * float(series.size() - 1 - i));
  const float cursor = area.xOf(double(state.frame().index));
  draw->AddLine(ImVec2(cursor, area.min.y), ImVec2(cursor, area.max.y), IM_COL32(255, 255, 255, 200), 1.0f);
  ImGui::InvisibleButton("plot", size);
  if (ImGui::IsItemActive() && area.max.x > area.min.x) state.goToFrame((long long)area.frameAt(ImGui::GetIO().MousePos.x));
}

// The shown diagnostic plots, two to a row, in [origin, origin + size].
void drawDiagnostics(AppState& state, ImVec2 origin, ImVec2 size) {
  const render::Analysis& a = state.bench().analysis();
  std::vector<DiagnosticRun> runs = {{&a.diagnostics, "A"}};
  if (a.comparison) runs.push_back({&a.comparison->diagnostics, "B", true});
  const size_t n = state.shownPlots.size(), columns = n > 1 ? 2 : 1;
  const float w = size.x / float(columns), h = kDiagnosticRowHeight;
  for (size_t i = 0; i < n; ++i) {
    const ImVec2 min(origin.x + w * float(i % columns), origin.y + h * float(i / columns));
    if (const DiagnosticPlot* plot = findDiagnosticPlot(state.shownPlots[i]))
      drawDiagnosticPlot(state, *plot, runs, ImVec2(min.x, min.y + 2), ImVec2(min.x + w - 4, min.y + h - 4));
  }
}

}  // namespace

void drawPlotsPanel(AppState& state) {
  const render::Analysis& a = state.bench().analysis();
  const ImGuiIO& io = ImGui::GetIO();
  const float width = io.DisplaySize.x - kLayersPanelWidth - kBenchPanelWidth;
  const float height = plotsPanelHeight(state.shownPlots.size());
  ImGui::SetNextWindowPos(ImVec2(kLayersPanelWidth, io.DisplaySize.y - kStatusBarHeight - kTimelineHeight - height), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Always);
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
  ImGui::SameLine();
  drawPlotMenu(state);
  const ImVec2 origin = ImGui::GetCursorScreenPos(), avail = ImGui::GetContentRegionAvail();
  const float diagnostics = height - kPlotsHeight;
  drawAtePlot(state, series, origin, ImVec2(avail.x, avail.y - diagnostics));
  if (diagnostics > 0) drawDiagnostics(state, ImVec2(origin.x, origin.y + avail.y - diagnostics), ImVec2(avail.x, diagnostics));
  ImGui::End();
}

}  // namespace hdprior::ui
