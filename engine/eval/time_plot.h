#pragma once
#include <string>
#include <vector>

#include "engine/eval/axis_ticks.h"
#include "engine/eval/rgb_image.h"

namespace hdprior {

// One line of a time plot: a value per x (NaN: a gap, the line breaks there), optionally a marker
// colour per point.
struct TimeSeries {
  std::string label;  // in the panel's legend; empty: left out of it
  std::vector<double> x, y;
  Rgb colour;
  std::vector<Rgb> markers;  // empty, or one per point
};

// One panel of a stack of time plots sharing their x axis.
struct TimePanel {
  std::string title;  // with the unit
  std::vector<TimeSeries> series;
};

// Where a panel draws its lines, in pixels: [left, right] x [top, bottom].
struct PlotRect {
  int left = 0, top = 0, right = 0, bottom = 0;
};

// Text size of every label, title and legend of a time plot.
inline constexpr int kTimePlotFontScale = 2;

// The panel's y ticks: from its finite values, with zero in the range; [0, 1] when none is finite.
AxisTicks valueTicks(const TimePanel& panel, int intervals);
// How wide the panel's y tick labels are, in pixels.
int tickLabelWidth(const AxisTicks& ticks);

// Draws the panel in `area`: its title and legend above the area, the frame, grid lines at both axes'
// ticks with y labels to the left, a line through each series' finite values and its markers. A
// panel without a finite value says so.
void drawTimePanel(RgbImage& image, const PlotRect& area, const AxisTicks& x, const AxisTicks& y, const TimePanel& panel);
// The x tick labels under `area` and the axis title under them.
void drawTimeAxisLabels(RgbImage& image, const PlotRect& area, const AxisTicks& x, const std::string& title);

}  // namespace hdprior
