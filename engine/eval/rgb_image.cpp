#include "engine/eval/rgb_image.h"

#include <algorithm>
#include <cmath>

namespace hdprior {

RgbImage::RgbImage(int w, int h, Rgb fill) : width(w), height(h), rgb(size_t(w) * size_t(h) * 3) {
  fillRect(0, 0, w, h, fill);
}

Rgb RgbImage::at(int x, int y) const {
  const uint8_t* p = rgb.data() + (size_t(y) * size_t(width) + size_t(x)) * 3;
  return {p[0], p[1], p[2]};
}

void RgbImage::set(int x, int y, Rgb c) {
  if (x < 0 || y < 0 || x >= width || y >= height) return;
  uint8_t* p = rgb.data() + (size_t(y) * size_t(width) + size_t(x)) * 3;
  p[0] = c.r;
  p[1] = c.g;
  p[2] = c.b;
}

void RgbImage::fillRect(int x0, int y0, int x1, int y1, Rgb c) {
  for (int y = std::max(y0, 0); y < std::min(y1, height); ++y) {
    for (int x = std::max(x0, 0); x < std::min(x1, width); ++x) set(x, y, c);
  }
}

void RgbImage::fillDisc(int cx, int cy, int radius, Rgb c) {
  for (int dy = -radius; dy <= radius; ++dy) {
    for (int dx = -radius; dx <= radius; ++dx) {
      if (dx * dx + dy * dy <= radius * radius + radius) set(cx + dx, cy + dy, c);
    }
  }
}

void RgbImage::drawLine(double x0, double y0, double x1, double y1, int thickness, Rgb c) {
  const int steps = std::max(1, int(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))));
  const int half = thickness / 2;
  for (int i = 0; i <= steps; ++i) {
    const double t = double(i) / steps;
    const int x = int(std::lround(x0 + t * (x1 - x0))) - half, y = int(std::lround(y0 + t * (y1 - y0))) - half;
    fillRect(x, y, x + thickness, y + thickness, c);
  }
}

}  // namespace hdprior
