#include "engine/eval/axis_ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hdprior {

int AxisTicks::count() const { return int(std::lround((high - low) / step)); }

double niceStep(double range, int intervals) {
  const double raw = range / double(intervals);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * magnitude >= raw) return m * magnitude;
  }
  return 10.0 * magnitude;
}

int tickDecimals(double step) { return std::max(0, -int(std::floor(std::log10(step) + 1e-9))); }

AxisTicks axisTicks(double low, double high, int intervals) {
  if (!(high > low)) {
    const double pad = std::abs(low) > 0 ? std::abs(low) * 0.5 : 1.0;
    low -= pad, high += pad;
  }
  AxisTicks t;
  t.step = niceStep(high - low, intervals);
  t.low = std::floor(low / t.step + 1e-9) * t.step;
  t.high = std::ceil(high / t.step - 1e-9) * t.step;
  t.decimals = tickDecimals(t.step);
  return t;
}

std::string tickLabel(double value, int decimals) {
  if (std::abs(value) < 1e-12) value = 0.0;  // no "-0.0"
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", decimals, value);
  return b;
}

}  // namespace hdprior
