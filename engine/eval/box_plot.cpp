#include "engine/eval/box_plot.h"

#include <algorithm>
#include <cmath>

#include "engine/eval/axis_ticks.h"
#include "engine/eval/bitmap_font.h"
#include "engine/eval/plot_colours.h"

namespace hdprior {
namespace {

constexpr int kFontScale = 2;
constexpr int kMargin = 16;
constexpr int kBoxTick = 6;
constexpr Rgb kWhite{255, 255, 255}, kBoxGrid{225, 225, 225}, kDot{90, 90, 90};

double quantile(const std::vector<double>& sorted, double p) {
  const double h = double(sorted.size() - 1) * p;
  const size_t lo = size_t(std::floor(h));
  if (lo + 1 >= sorted.size()) return sorted.back();
  return sorted[lo] + (h - double(lo)) * (sorted[lo + 1] - sorted[lo]);
}

Rgb darker(Rgb c) { return {uint8_t(c.r * 0.6), uint8_t(c.g * 0.6), uint8_t(c.b * 0.6)}; }

void hline(RgbImage& im, int x0, int x1, int y, int thickness, Rgb c) { im.fillRect(x0, y - thickness / 2, x1 + 1, y - thickness / 2 + thickness, c); }
void vline(RgbImage& im, int x, int y0, int y1, int thickness, Rgb c) {
  im.fillRect(x - thickness / 2, std::min(y0, y1), x - thickness / 2 + thickness, std::max(y0, y1) + 1, c);
}

void drawCentred(RgbImage& im, int cx, int y, const std::string& text, Rgb c) {
  drawText(im, cx - textWidth(text, kFontScale) / 2, y, text, kFontScale, c);
}

void drawAxis(RgbImage& im, const BoxPlotLayout& L, const BoxPlotOptions& o) {
  const int ticks = int(std::round(L.yMax / L.yTick));
  for (int k = 0; k <= ticks; ++k) {
    const double v = k * L.yTick;
    const int y = L.yPixel(v);
    if (k > 0) hline(im, L.left, L.right, y, 1, kBoxGrid);
    hline(im, L.left - kBoxTick, L.left, y, 2, kAxisColour);
    const std::string label = tickLabel(v, L.tickDecimals);
    drawText(im, L.left - kBoxTick - 4 - textWidth(label, kFontScale), y - capHeight(kFontScale) / 2, label, kFontScale, kTextColour);
  }
  drawCentred(im, (L.left + L.right) / 2, kMargin, o.title, kTextColour);
  drawText(im, kMargin, (L.top + L.bottom) / 2 + textWidth(o.yTitle, kFontScale) / 2, o.yTitle, kFontScale, kTextColour,
           TextDirection::Upwards);
}

void drawBox(RgbImage& im, const BoxPlotLayout& L, int cx, const BoxPlotSeries& s) {
  const BoxStats b = boxStats(s.values);
  const int w = L.boxHalfWidth;
  drawCentred(im, cx, L.bottom + 14, s.label, kTextColour);
  drawCentred(im, cx, L.bottom + 14 + textHeight(kFontScale) + 8, "n = " + std::to_string(b.count), kTextColour);
  if (b.count == 0) return;
  const int yq1 = L.yPixel(b.q1), yq3 = L.yPixel(b.q3), yLow = L.yPixel(b.whiskerLow), yHigh = L.yPixel(b.whiskerHigh);
  vline(im, cx, yHigh, yq3, 2, s.colour);
  vline(im, cx, yq1, yLow, 2, s.colour);
  hline(im, cx - w / 2, cx + w / 2, yHigh, 2, s.colour);
  hline(im, cx - w / 2, cx + w / 2, yLow, 2, s.colour);
  im.fillRect(cx - w, yq3, cx + w + 1, yq1 + 1, boxFill(s.colour));
  hline(im, cx - w, cx + w, yq3, 2, s.colour);
  hline(im, cx - w, cx + w, yq1, 2, s.colour);
  vline(im, cx - w, yq3, yq1, 2, s.colour);
  vline(im, cx + w, yq3, yq1, 2, s.colour);
  for (size_t i = 0; i < s.values.size(); ++i) {
    const double v = s.values[i];
    if (v < b.whiskerLow || v > b.whiskerHigh) continue;
    const double jitter = 2.0 * std::fmod(0.5 + double(i) * 0.6180339887, 1.0) - 1.0;  // golden-ratio sequence in [-1, 1)
    im.fillDisc(cx + int(std::lround(jitter * 0.6 * w)), L.yPixel(v), 3, kDot);
  }
  hline(im, cx - w, cx + w, L.yPixel(b.median), 4, darker(s.colour));
  for (double v : b.outliers) im.fillDisc(cx, L.yPixel(v), 5, s.colour);
}

}  // namespace

BoxStats boxStats(std::vector<double> values) {
  BoxStats s;
  s.count = values.size();
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  s.q1 = quantile(values, 0.25);
  s.median = quantile(values, 0.5);
  s.q3 = quantile(values, 0.75);
  const double reach = 1.5 * (s.q3 - s.q1);
  s.whiskerLow = s.q1;
  s.whiskerHigh = s.q3;
  for (double v : values) {
    if (v < s.q1 - reach || v > s.q3 + reach) {
      s.outliers.push_back(v);
    } else {
      s.whiskerLow = std::min(s.whiskerLow, v);
      s.whiskerHigh = std::max(s.whiskerHigh, v);
    }
  }
  return s;
}

int BoxPlotLayout::yPixel(double value) const {
  return bottom - int(std::lround(value / yMax * double(bottom - top)));
}

BoxPlotLayout boxPlotLayout(const std::vector<BoxPlotSeries>& series, const BoxPlotOptions& o) {
  BoxPlotLayout L;
  double maxValue = 0;
  for (const auto& s : series) {
    for (double v : s.values) maxValue = std::max(maxValue, v);
  }
  if (maxValue > 0) {
    L.yTick = niceStep(maxValue * 1.05, 8);  // 4 to 8 intervals
    L.yMax = std::ceil(maxValue * 1.05 / L.yTick) * L.yTick;
  }
  L.tickDecimals = tickDecimals(L.yTick);
  const int labelWidth = textWidth(tickLabel(L.yMax, L.tickDecimals), kFontScale);
  L.left = kMargin + textHeight(kFontScale) + 12 + labelWidth + 4 + kBoxTick;
  L.top = kMargin + textHeight(kFontScale) + 24;
  L.right = o.width - 24;
  L.bottom = o.height - kMargin - 2 * textHeight(kFontScale) - 30;
  const int slot = (L.right - L.left) / std::max<int>(1, int(series.size()));
  L.boxHalfWidth = std::min(slot * 22 / 100, 70);
  for (size_t i = 0; i < series.size(); ++i) L.centres.push_back(L.left + slot * int(i) + slot / 2);
  return L;
}

Rgb boxFill(Rgb c) {
  auto tint = [](uint8_t v) { return uint8_t(v + (255 - v) * 3 / 4); };
  return {tint(c.r), tint(c.g), tint(c.b)};
}

RgbImage drawBoxPlot(const std::vector<BoxPlotSeries>& series, const BoxPlotOptions& o) {
  const BoxPlotLayout L = boxPlotLayout(series, o);
  RgbImage im(o.width, o.height, kWhite);
  drawAxis(im, L, o);
  for (size_t i = 0; i < series.size(); ++i) drawBox(im, L, L.centres[i], series[i]);
  vline(im, L.left, L.top, L.bottom, 2, kAxisColour);
  hline(im, L.left, L.right, L.bottom, 2, kAxisColour);
  return im;
}

}  // namespace hdprior
