#pragma once
#include <string>

namespace hdprior {

// A figure axis's ticks: every `step` from `low` to `high` (both multiples of the step), labelled
// with `decimals` digits after the point.
struct AxisTicks {
  double low = 0, high = 1, step = 0.2;
  int decimals = 1;
  int count() const;              // intervals from low to high
  double at(int k) const { return low + k * step; }
};

// The tick step for `range`: 1, 2 or 5 x 10^k giving at most `intervals` intervals.
double niceStep(double range, int intervals);
// The digits after the point a label of `step`'s multiples needs.
int tickDecimals(double step);
// Ticks covering [low, high] outwards with at most about `intervals` intervals; a range of zero width
// becomes one step around the value.
AxisTicks axisTicks(double low, double high, int intervals);
// "2.50", "-0.4", "300".
std::string tickLabel(double value, int decimals);

}  // namespace hdprior
