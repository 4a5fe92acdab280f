#pragma once
#include <string>
#include <vector>

#include "engine/eval/rgb_image.h"

namespace hdprior {

// Tukey's box: quartiles by linear interpolation between order statistics (R's type 7), whiskers at
// the most extreme values within 1.5 IQR of the box, everything beyond them an outlier.
struct BoxStats {
  size_t count = 0;
  double q1 = 0, median = 0, q3 = 0;
  double whiskerLow = 0, whiskerHigh = 0;
  std::vector<double> outliers;  // ascending
};
BoxStats boxStats(std::vector<double> values);

struct BoxPlotSeries {
  std::string label;
  std::vector<double> values;
  Rgb colour;  // outline, median, whiskers and outliers; the box is filled with a light tint of it
};

struct BoxPlotOptions {
  int width = 720, height = 540;
  std::string title, yTitle;
};

// Where a box plot puts things: the plot area (pixels), the y axis (from 0) and the box centres.
struct BoxPlotLayout {
  int left = 0, top = 0, right = 0, bottom = 0;
  double yMax = 1, yTick = 0.2;
  int tickDecimals = 1;
  std::vector<int> centres;
  int boxHalfWidth = 0;

  int yPixel(double value) const;
};
BoxPlotLayout boxPlotLayout(const std::vector<BoxPlotSeries>& series, const BoxPlotOptions& options);

// The figure on a white background: title, y axis with ticks, grid and labels in the series' unit,
// one box per series with its label and count below it, whiskers, outliers as dots, and every
// other value as a small grey dot jittered (deterministically) across the box.
RgbImage drawBoxPlot(const std::vector<BoxPlotSeries>& series, const BoxPlotOptions& options);

// The light tint a box is filled with.
Rgb boxFill(Rgb colour);

}  // namespace hdprior
