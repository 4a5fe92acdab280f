#include "engine/eval/time_plot.h"

#include <algorithm>
#include <cmath>

#include "engine/eval/bitmap_font.h"
#include "engine/eval/plot_colours.h"

namespace hdprior {
namespace {

constexpr int kScale = kTimePlotFontScale;
constexpr int kPanelTick = 5;
constexpr Rgb kPanelGrid{228, 228, 228}, kZero{170, 170, 170}, kBackground{250, 250, 250};

double xPixel(const PlotRect& a, const AxisTicks& x, double v) { return a.left + (v - x.low) / (x.high - x.low) * (a.right - a.left); }
double yPixel(const PlotRect& a, const AxisTicks& y, double v) { return a.bottom - (v - y.low) / (y.high - y.low) * (a.bottom - a.top); }

bool anyFinite(const TimePanel& panel) {
  for (const TimeSeries& s : panel.series)
    if (std::any_of(s.y.begin(), s.y.end(), [](double v) { return std::isfinite(v); })) return true;
  return false;
}

void drawGrid(RgbImage& im, const PlotRect& a, const AxisTicks& x, const AxisTicks& y) {
  im.fillRect(a.left, a.top, a.right + 1, a.bottom + 1, kBackground);
  for (int k = 0; k <= x.count(); ++k) {
    const int px = int(std::lround(xPixel(a, x, x.at(k))));
    im.fillRect(px, a.top, px + 1, a.bottom, kPanelGrid);
    im.fillRect(px, a.bottom, px + 1, a.bottom + kPanelTick, kAxisColour);
  }
  for (int k = 0; k <= y.count(); ++k) {
    const double v = y.at(k);
    const int py = int(std::lround(yPixel(a, y, v)));
    im.fillRect(a.left, py, a.right, py + 1, std::abs(v) < 1e-12 ? kZero : kPanelGrid);
    im.fillRect(a.left - kPanelTick, py, a.left, py + 1, kAxisColour);
    const std::string label = tickLabel(v, y.decimals);
    drawText(im, a.left - kPanelTick - 4 - textWidth(label, kScale), py - capHeight(kScale) / 2, label, kScale, kTextColour);
  }
  im.fillRect(a.left - 1, a.top, a.left + 1, a.bottom + 1, kAxisColour);
  im.fillRect(a.left - 1, a.bottom, a.right + 1, a.bottom + 2, kAxisColour);
}

// A line through the finite values, broken where one is missing.
void drawLine(RgbImage& im, const PlotRect& a, const AxisTicks& x, const AxisTicks& y, const TimeSeries& s) {
  for (size_t i = 0; i + 1 < s.y.size(); ++i) {
    if (!std::isfinite(s.y[i]) || !std::isfinite(s.y[i + 1])) continue;
    im.drawLine(xPixel(a, x, s.x[i]), yPixel(a, y, s.y[i]), xPixel(a, x, s.x[i + 1]), yPixel(a, y, s.y[i + 1]), 2, s.colour);
  }
}

// Markers shrink as the points crowd, so that the lines stay visible: radius 3 with 12 pixels or more
// per point, a single pixel below 4.
int markerRadius(const PlotRect& a, size_t points) {
  const double spacing = double(a.right - a.left) / double(std::max<size_t>(points, 1));
  return std::clamp(int(spacing / 4.0), 0, 3);
}

void drawMarkers(RgbImage& im, const PlotRect& a, const AxisTicks& x, const AxisTicks& y, const TimeSeries& s) {
  const int radius = markerRadius(a, s.y.size());
  for (size_t i = 0; i < s.y.size() && i < s.markers.size(); ++i) {
    if (std::isfinite(s.y[i]))
      im.fillDisc(int(std::lround(xPixel(a, x, s.x[i]))), int(std::lround(yPixel(a, y, s.y[i]))), radius, s.markers[i]);
  }
}

// The labelled series as colour bars with their labels, right-aligned above the area.
void drawLegend(RgbImage& im, const PlotRect& a, const TimePanel& panel) {
  int x = a.right;
  const int y = a.top - textHeight(kScale) - 4;
  for (auto s = panel.series.rbegin(); s != panel.series.rend(); ++s) {
    if (s->label.empty()) continue;
    x -= textWidth(s->label, kScale);
    drawText(im, x, y, s->label, kScale, kTextColour);
    x -= 24;
    im.fillRect(x, y + capHeight(kScale) / 2 - 1, x + 18, y + capHeight(kScale) / 2 + 2, s->colour);
    x -= 14;
  }
}

}  // namespace

AxisTicks valueTicks(const TimePanel& panel, int intervals) {
  double lo = 0.0, hi = 0.0;
  for (const TimeSeries& s : panel.series)
    for (double v : s.y)
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  return hi > lo ? axisTicks(lo, hi, intervals) : axisTicks(0.0, 1.0, intervals);
}

int tickLabelWidth(const AxisTicks& ticks) {
  int w = 0;
  for (int k = 0; k <= ticks.count(); ++k) w = std::max(w, textWidth(tickLabel(ticks.at(k), ticks.decimals), kScale));
  return w + kPanelTick + 4;
}

void drawTimePanel(RgbImage& im, const PlotRect& a, const AxisTicks& x, const AxisTicks& y, const TimePanel& panel) {
  drawGrid(im, a, x, y);
  drawText(im, a.left, a.top - textHeight(kScale) - 4, panel.title, kScale, kTextColour);
  drawLegend(im, a, panel);
  if (!anyFinite(panel)) {
    const std::string none = "no values";
    drawText(im, (a.left + a.right - textWidth(none, kScale)) / 2, (a.top + a.bottom - capHeight(kScale)) / 2, none, kScale, kZero);
    return;
  }
  for (const TimeSeries& s : panel.series) drawLine(im, a, x, y, s);
  for (const TimeSeries& s : panel.series) drawMarkers(im, a, x, y, s);
}

void drawTimeAxisLabels(RgbImage& im, const PlotRect& a, const AxisTicks& x, const std::string& title) {
  const int y = a.bottom + kPanelTick + 6;
  for (int k = 0; k <= x.count(); ++k) {
    const std::string label = tickLabel(x.at(k), x.decimals);
    drawText(im, int(std::lround(xPixel(a, x, x.at(k)))) - textWidth(label, kScale) / 2, y, label, kScale, kTextColour);
  }
  drawText(im, (a.left + a.right - textWidth(title, kScale)) / 2, y + textHeight(kScale) + 6, title, kScale, kTextColour);
}

}  // namespace hdprior
