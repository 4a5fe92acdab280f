#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hdprior {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

// A plain 8-bit RGB raster (rows top to bottom) for figures drawn without a GPU. Drawing outside
// the image is clipped.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // width * height * 3

  RgbImage() = default;
  RgbImage(int w, int h, Rgb fill);

  Rgb at(int x, int y) const;
  void set(int x, int y, Rgb c);
  void fillRect(int x0, int y0, int x1, int y1, Rgb c);  // [x0, x1) x [y0, y1)
  void fillDisc(int cx, int cy, int radius, Rgb c);
  // A straight line between two points in pixel coordinates, `thickness` pixels wide.
  void drawLine(double x0, double y0, double x1, double y1, int thickness, Rgb c);
};

}  // namespace hdprior
