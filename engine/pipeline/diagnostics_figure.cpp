#include "engine/pipeline/diagnostics_figure.h"

#include <algorithm>
#include <cmath>

#include "engine/eval/bitmap_font.h"
#include "engine/eval/time_plot.h"
#include "engine/pipeline/constraint_colour.h"

namespace hdprior {
namespace {

constexpr int kScale = kTimePlotFontScale;
constexpr int kMargin = 16, kTitleRow = 28, kPanelGap = 14, kAxisRows = 60;
constexpr int kYIntervals = 4, kXIntervals = 12, kStripHeight = 10;
constexpr Rgb kWhite{255, 255, 255}, kText{30, 30, 30};
// Line colours: [run][series]; run A dark grey and orange, run B violet and teal.
constexpr Rgb kLineColours[2][2] = {{{40, 40, 40}, {235, 120, 20}}, {{140, 50, 210}, {0, 155, 155}}};

Rgb rgbOf(ConstraintClass c) {
  const Eigen::Vector4f v = constraintColour(c);
  return {uint8_t(std::lround(v.x() * 255)), uint8_t(std::lround(v.y() * 255)), uint8_t(std::lround(v.z() * 255))};
}
Rgb statusColour(const PriorConstraint& c) { return rgbOf(constraintClass(c)); }

// Draws `text` with its top-left corner at (x, y); returns the x where it ends.
int drawTextRun(RgbImage& im, int x, int y, const std::string& text, Rgb colour) {
  drawText(im, x, y, text, kScale, colour);
  return x + textWidth(text, kScale);
}

std::string runLetter(size_t run) { return run == 0 ? "A" : "B"; }

TimeSeries fieldSeries(const std::vector<KeyframeDiagnostic>& rows, DiagnosticField field, bool markers) {
  TimeSeries s;
  for (const KeyframeDiagnostic& d : rows) {
    s.x.push_back(double(d.frame));
    s.y.push_back(d[field]);
    if (markers) s.markers.push_back(statusColour(d.constraint));
  }
  return s;
}

// A line's legend label: the series' own with several series, run letters with several runs.
std::string seriesLabel(const DiagnosticPlot& plot, size_t series, size_t run, size_t runs) {
  const std::string own = plot.series.size() > 1 ? plot.series[series].label : "";
  if (runs < 2) return own;
  return own.empty() ? runLetter(run) : runLetter(run) + " " + own;
}

TimePanel panelOf(const DiagnosticPlot& plot, const std::vector<DiagnosticsRun>& runs) {
  TimePanel panel{plot.title, {}};
  for (size_t r = 0; r < runs.size(); ++r) {
    if (plot.threshold) {
      TimeSeries gate = fieldSeries(runs[r].rows, *plot.threshold, false);
      gate.colour = kDiagnosticsThresholdColour;
      gate.label = r == 0 ? "gate" : "";
      panel.series.push_back(std::move(gate));
    }
    for (size_t i = 0; i < plot.series.size(); ++i) {
      TimeSeries s = fieldSeries(runs[r].rows, plot.series[i].field, i == 0);
      s.colour = diagnosticsLineColour(r, i);
      s.label = seriesLabel(plot, i, r, runs.size());
      panel.series.push_back(std::move(s));
    }
  }
  return panel;
}

AxisTicks frameTicks(const std::vector<DiagnosticsRun>& runs) {
  double last = 1.0;
  for (const DiagnosticsRun& run : runs)
    for (const KeyframeDiagnostic& d : run.rows) last = std::max(last, double(d.frame));
  return axisTicks(0.0, last, kXIntervals);
}

// The header's second row: a disc and a name per status a marker can have.
void drawStatusLegend(RgbImage& im, int x, int y) {
  x = drawTextRun(im, x, y, "marker: keyframe status", kText) + 20;
  for (size_t c = 0; c < kConstraintClasses; ++c) {
    if (ConstraintClass(c) == ConstraintClass::NoPrior) continue;  // every keyframe in keyframes.json has a match
    im.fillDisc(x + 5, y + capHeight(kScale) / 2, 5, rgbOf(ConstraintClass(c)));
    x = drawTextRun(im, x + 16, y, kConstraintClassNames[c], kText) + 20;
  }
}

// One band per run under the header: a tick per keyframe in its status colour, readable where the
// markers crowd into single pixels.
int drawStatusStrips(RgbImage& im, const std::vector<DiagnosticsRun>& runs, const AxisTicks& x, const PlotRect& area) {
  const std::string title = runs.size() > 1 ? "status per keyframe (A, then B)" : "status per keyframe";
  drawTextRun(im, area.left, area.top - textHeight(kScale) - 4, title, kText);
  int y = area.top;
  for (const DiagnosticsRun& run : runs) {
    for (const KeyframeDiagnostic& d : run.rows) {
      const double px = area.left + (double(d.frame) - x.low) / (x.high - x.low) * (area.right - area.left);
      im.fillRect(int(std::lround(px)) - 1, y, int(std::lround(px)) + 2, y + kStripHeight, statusColour(d.constraint));
    }
    y += kStripHeight + 3;
  }
  return y;
}

void drawHeader(RgbImage& im, const std::vector<DiagnosticsRun>& runs) {
  int x = drawTextRun(im, kMargin, kMargin, "keyframe diagnostics", kText) + 24;
  for (size_t r = 0; r < runs.size(); ++r) {
    const std::string name = runs.size() > 1 ? runLetter(r) + ": " + runs[r].name : runs[r].name;
    if (runs.size() > 1) {
      im.fillRect(x, kMargin + capHeight(kScale) / 2 - 1, x + 22, kMargin + capHeight(kScale) / 2 + 2, diagnosticsLineColour(r, 0));
      x += 30;
    }
    x = drawTextRun(im, x, kMargin, name + " (" + std::to_string(runs[r].rows.size()) + " keyframes)", kText) + 24;
  }
  drawStatusLegend(im, kMargin, kMargin + textHeight(kScale) + 8);
}

}  // namespace

Rgb diagnosticsLineColour(size_t run, size_t series) { return kLineColours[std::min<size_t>(run, 1)][series % 2]; }

std::vector<const DiagnosticPlot*> plotsWithValues(const std::vector<DiagnosticsRun>& runs) {
  std::vector<const DiagnosticPlot*> plots;
  for (const DiagnosticPlot& plot : diagnosticPlots()) {
    bool any = false;
    for (const DiagnosticsRun& run : runs)
      for (const KeyframeDiagnostic& d : run.rows)
        for (const DiagnosticPlot::Series& s : plot.series) any = any || std::isfinite(d[s.field]);
    if (any) plots.push_back(&plot);
  }
  return plots;
}

RgbImage drawDiagnosticsFigure(const std::vector<DiagnosticsRun>& runs, const std::vector<const DiagnosticPlot*>& plots,
                               const DiagnosticsFigureOptions& o) {
  std::vector<TimePanel> panels;
  std::vector<AxisTicks> yTicks;
  int labelWidth = 0;
  for (const DiagnosticPlot* plot : plots) {
    panels.push_back(panelOf(*plot, runs));
    yTicks.push_back(valueTicks(panels.back(), kYIntervals));
    labelWidth = std::max(labelWidth, tickLabelWidth(yTicks.back()));
  }
  const int stripTop = kMargin + 2 * textHeight(kScale) + 16 + kTitleRow;
  const int top = stripTop + int(runs.size()) * (kStripHeight + 3) + kPanelGap;
  const int height = top + int(panels.size()) * (kTitleRow + o.panelHeight + kPanelGap) + kAxisRows;
  RgbImage im(o.width, height, kWhite);
  drawHeader(im, runs);
  const AxisTicks x = frameTicks(runs);
  PlotRect area{kMargin + labelWidth, stripTop, o.width - kMargin - 8, stripTop};
  drawStatusStrips(im, runs, x, area);
  for (size_t p = 0; p < panels.size(); ++p) {
    area.top = top + int(p) * (kTitleRow + o.panelHeight + kPanelGap) + kTitleRow;
    area.bottom = area.top + o.panelHeight;
    drawTimePanel(im, area, x, yTicks[p], panels[p]);
  }
  drawTimeAxisLabels(im, area, x, "frame (sweep index of the log)");
  return im;
}

}  // namespace hdprior
