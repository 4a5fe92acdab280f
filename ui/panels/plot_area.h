#pragma once
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace hdprior::ui {

// A plot's rectangle on screen: frames of the log across, values [low, high] up (clamped).
struct PlotArea {
  ImVec2 min, max;
  size_t frames = 1;
  double low = 0.0, high = 1.0;
  float xOf(double frame) const {
    return min.x + (max.x - min.x) * float(frame / double(std::max<size_t>(1, frames - 1)));
  }
  float yOf(double value) const {
    const double t = (std::clamp(value, low, high) - low) / std::max(high - low, 1e-12);
    return max.y - (max.y - min.y) * float(t);
  }
  ImVec2 at(double frame, double value) const { return {xOf(frame), yOf(value)}; }
  // The frame under screen x, clamped to the log.
  size_t frameAt(float x) const {
    const float t = std::clamp((x - min.x) / std::max(max.x - min.x, 1.0f), 0.0f, 1.0f);
    return size_t(std::lround(t * float(std::max<size_t>(1, frames) - 1)));
  }
  bool contains(const ImVec2& p) const { return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y; }
};

// 1, 2 or 5 times a power of ten, at least v.
inline double niceCeiling(double v) {
  const double p = std::pow(10.0, std::floor(std::log10(std::max(v, 1e-3))));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (v <= m * p) return m * p;
  return 10.0 * p;
}

}  // namespace hdprior::ui
