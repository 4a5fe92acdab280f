#include "render/overlays/colour_bar.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hdprior::render {

std::string colourBarLabel(double value, const std::string& unit) {
  char number[32];
  std::snprintf(number, sizeof number, std::abs(value) >= 100.0 ? "%.0f" : "%.3g", value);
  return unit.empty() ? number : std::string(number) + " " + unit;
}

OverlayBlock colourBar(const ScreenCanvas& canvas, const ColourScale& scale) {
  const float u = canvas.unit(), gap = 3 * u, barHeight = 6 * u;
  const std::string low = colourBarLabel(scale.low, scale.unit);
  const std::string high = colourBarLabel(scale.high, scale.unit) + (scale.openHigh ? "+" : "");
  const float width = std::max({120 * u, canvas.textWidth(scale.title),
                                canvas.textWidth(low) + canvas.textWidth(high) + 4 * u});
  const float height = 2 * canvas.capHeight() + 2 * gap + barHeight;
  OverlayBlock block;
  block.size = {width, height};
  block.draw = [=](ScreenCanvas& c, const Eigen::Vector2f& at) {
    c.text(at.x(), at.y(), scale.title, kOverlayText);
    const float barTop = at.y() + c.capHeight() + gap, labelTop = barTop + barHeight + gap;
    c.ramp(at.x(), barTop, at.x() + width, barTop + barHeight, scale.map);
    c.text(at.x(), labelTop, low, kOverlayText);
    c.text(at.x() + width - c.textWidth(high), labelTop, high, kOverlayText);
  };
  return block;
}

}  // namespace hdprior::render
