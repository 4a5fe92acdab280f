#include "render/overlays/scale_bar.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hdprior::render {

double scaleBarLength(double metresPerPixel, double maxPixels) {
  const double longest = metresPerPixel * maxPixels;
  const double decade = std::pow(10.0, std::floor(std::log10(longest)));
  for (const double step : {5.0, 2.0, 1.0})
    if (step * decade <= longest * (1 + 1e-9)) return step * decade;
  return decade;  // not reached: decade <= longest
}

std::string scaleBarLabel(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%g m", metres);
  return text;
}

OverlayBlock scaleBar(const ScreenCanvas& canvas, double metresPerPixel, double maxPixels) {
  const double metres = scaleBarLength(metresPerPixel, maxPixels);
  const float u = canvas.unit(), length = float(metres / metresPerPixel), tick = 5 * u, thickness = 2 * u;
  const std::string label = scaleBarLabel(metres);
  OverlayBlock block;
  block.size = {std::max(length, canvas.textWidth(label)), canvas.capHeight() + 3 * u + tick};
  block.draw = [=](ScreenCanvas& c, const Eigen::Vector2f& at) {
    c.text(at.x() + (length - c.textWidth(label)) / 2, at.y(), label, kOverlayText);
    const float bottom = at.y() + c.capHeight() + 3 * u + tick;
    c.rect(at.x(), bottom - thickness, at.x() + length, bottom, kOverlayText);
    c.rect(at.x(), bottom - tick, at.x() + thickness, bottom, kOverlayText);
    c.rect(at.x() + length - thickness, bottom - tick, at.x() + length, bottom, kOverlayText);
  };
  return block;
}

}  // namespace hdprior::render
