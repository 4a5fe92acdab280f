#include "ui/panels/diagnostic_plot_view.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "render/constraint_palette.h"
#include "ui/app_state.h"
#include "ui/panels/plot_area.h"

namespace hdprior::ui {
namespace {

constexpr ImU32 kSeriesColours[] = {IM_COL32(235, 235, 235, 255), IM_COL32(255, 150, 60, 255)};
constexpr ImU32 kThresholdColour = IM_COL32(255, 70, 70, 220);
constexpr ImU32 kComparisonColours[] = {IM_COL32(77, 255, 191, 255), IM_COL32(40, 190, 140, 255)};  // run B, as its trajectory

ImU32 classColour(const PriorConstraint& c) {
  const Eigen::Vector4f v = render::constraintColour(render::constraintClass(c));
  return ImColor(v.x(), v.y(), v.z(), v.w());
}

// The value range of every line and threshold, rounded outwards; [0, 1] when nothing is finite.
void fitRange(PlotArea& area, const DiagnosticPlot& plot, const std::vector<DiagnosticRun>& runs) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const DiagnosticRun& run : runs)
    for (const KeyframeDiagnostic& d : *run.rows) {
      for (const DiagnosticPlot::Series& s : plot.series)
        if (std::isfinite(d[s.field])) lo = std::min(lo, d[s.field]), hi = std::max(hi, d[s.field]);
      if (plot.threshold && std::isfinite(d[*plot.threshold])) hi = std::max(hi, d[*plot.threshold]);
    }
  if (!(lo <= hi)) lo = 0.0, hi = 1.0;
  area.high = hi > 0 ? niceCeiling(hi) : 0.0;
  area.low = lo >= 0 ? 0.0 : -niceCeiling(-lo);
  if (area.high <= area.low) area.high = area.low + 1.0;
}

void polyline(ImDrawList* draw, const std::vector<ImVec2>& line, ImU32 colour, bool dashed) {
  if (line.size() < 2) return;
  if (!dashed) {
    draw->AddPolyline(line.data(), int(line.size()), colour, 0, 1.5f);
    return;
  }
  for (size_t i = 0; i + 1 < line.size(); i += 2) draw->AddLine(line[i], line[i + 1], colour, 1.5f);
}

// A line through the keyframes' finite values, broken where one is missing.
void drawField(ImDrawList* draw, const PlotArea& area, const std::vector<KeyframeDiagnostic>& rows, DiagnosticField field,
               ImU32 colour, bool dashed) {
  std::vector<ImVec2> line;
  for (const KeyframeDiagnostic& d : rows) {
    if (std::isfinite(d[field])) {
      line.push_back(area.at(double(d.frame), d[field]));
      continue;
    }
    polyline(draw, line, colour, dashed);
    line.clear();
  }
  polyline(draw, line, colour, dashed);
}

void drawMarkers(ImDrawList* draw, const PlotArea& area, const std::vector<KeyframeDiagnostic>& rows, DiagnosticField field) {
  for (const KeyframeDiagnostic& d : rows)
    if (std::isfinite(d[field])) draw->AddCircleFilled(area.at(double(d.frame), d[field]), 2.5f, classColour(d.constraint));
}

void drawFrame(ImDrawList* draw, const PlotArea& area, const DiagnosticPlot& plot) {
  const ImU32 text = IM_COL32(200, 200, 200, 255);
  draw->AddRectFilled(area.min, area.max, IM_COL32(0, 0, 0, 60));
  draw->AddRect(area.min, area.max, IM_COL32(255, 255, 255, 90));
  if (area.low < 0 && area.high > 0)
    draw->AddLine(ImVec2(area.min.x, area.yOf(0)), ImVec2(area.max.x, area.yOf(0)), IM_COL32(255, 255, 255, 40));
  char label[32];
  std::snprintf(label, sizeof label, "%.3g", area.high);
  draw->AddText(ImVec2(area.min.x - 40, area.min.y - 2), text, label);
  std::snprintf(label, sizeof label, "%.3g", area.low);
  draw->AddText(ImVec2(area.min.x - 40, area.max.y - 12), text, label);
  draw->AddText(ImVec2(area.min.x + 4, area.min.y + 1), text, plot.title);
}

// The keyframe whose frame is nearest `frame` among the rows, or nullptr.
const KeyframeDiagnostic* nearest(const std::vector<KeyframeDiagnostic>& rows, size_t frame) {
  const KeyframeDiagnostic* best = nullptr;
  for (const KeyframeDiagnostic& d : rows)
    if (!best || std::abs(double(d.frame) - double(frame)) < std::abs(double(best->frame) - double(frame))) best = &d;
  return best;
}

std::string valueText(double v) {
  if (!std::isfinite(v)) return "-";
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

void hover(AppState& state, const DiagnosticPlot& plot, const std::vector<DiagnosticRun>& runs, const PlotArea& area) {
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  if (!ImGui::IsWindowHovered() || !area.contains(mouse) || runs.empty()) return;
  const KeyframeDiagnostic* d = nearest(*runs[0].rows, area.frameAt(mouse.x));
  if (!d) return;
  const float x = area.xOf(double(d->frame));
  ImGui::GetWindowDrawList()->AddLine(ImVec2(x, area.min.y), ImVec2(x, area.max.y), IM_COL32(255, 255, 255, 90));
  ImGui::BeginTooltip();
  ImGui::Text("keyframe %zu, frame %zu", d->keyframe, d->frame);
  for (const DiagnosticRun& run : runs) {
    const KeyframeDiagnostic* r = run.rows == runs[0].rows ? d : nearest(*run.rows, d->frame);
    if (!r) continue;
    std::string line = runs.size() > 1 ? std::string(run.name) + ": " : std::string();
    for (const DiagnosticPlot::Series& s : plot.series) line += std::string(s.label) + " " + valueText((*r)[s.field]) + "  ";
    if (plot.threshold) line += "gate " + valueText((*r)[*plot.threshold]);
    ImGui::TextUnformatted(line.c_str());
    ImGui::TextColored(ImColor(classColour(r->constraint)), "%s", r->constraint.label().c_str());
  }
  ImGui::EndTooltip();
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) state.inspectKeyframe(d->keyframe);
}

}  // namespace

void drawDiagnosticPlot(AppState& state, const DiagnosticPlot& plot, const std::vector<DiagnosticRun>& runs, ImVec2 min,
                        ImVec2 max) {
  PlotArea area{ImVec2(min.x + 44, min.y + 2), ImVec2(max.x - 4, max.y - 2)};
  area.frames = state.frameCount();
  fitRange(area, plot, runs);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  drawFrame(draw, area, plot);
  draw->PushClipRect(area.min, area.max, true);
  for (const DiagnosticRun& run : runs) {
    if (plot.threshold) drawField(draw, area, *run.rows, *plot.threshold, kThresholdColour, run.dashed);
    for (size_t i = 0; i < plot.series.size(); ++i)
      drawField(draw, area, *run.rows, plot.series[i].field, (run.dashed ? kComparisonColours : kSeriesColours)[i % 2], run.dashed);
    drawMarkers(draw, area, *run.rows, plot.series[0].field);
  }
  const float playhead = area.xOf(double(state.frame().index));
  draw->AddLine(ImVec2(playhead, area.min.y), ImVec2(playhead, area.max.y), IM_COL32(255, 255, 255, 200), 1.0f);
  draw->PopClipRect();
  hover(state, plot, runs, area);
}

}  // namespace hdprior::ui
