#include "render/overlays/screen_canvas.h"

#include <cmath>
#include <numbers>

#include "engine/eval/bitmap_font.h"
#include "render/camera.h"

namespace hdprior::render {
namespace {

void triangle(std::vector<ColoredVertex>& out, const ColoredVertex& a, const ColoredVertex& b, const ColoredVertex& c) {
  out.insert(out.end(), {a, b, c});
}

Eigen::Vector4f opaque(const Eigen::Vector3f& c) { return {c.x(), c.y(), c.z(), 1.0f}; }

}  // namespace

ScreenCanvas::ScreenCanvas(int width, int height, int fontScale)
    : width_(width), height_(height), fontScale_(std::max(1, fontScale)) {}

void ScreenCanvas::rect(float x0, float y0, float x1, float y1, const Eigen::Vector4f& colour) {
  const ColoredVertex a{{x0, y0, 0}, colour}, b{{x1, y0, 0}, colour}, c{{x1, y1, 0}, colour}, d{{x0, y1, 0}, colour};
  triangle(triangles_, a, b, c);
  triangle(triangles_, a, c, d);
}

void ScreenCanvas::ramp(float x0, float y0, float x1, float y1, Eigen::Vector3f (*map)(float), int steps) {
  for (int i = 0; i < steps; ++i) {
    const float t0 = float(i) / steps, t1 = float(i + 1) / steps;
    const float left = x0 + (x1 - x0) * t0, right = x0 + (x1 - x0) * t1;
    const Eigen::Vector4f c0 = opaque(map(t0)), c1 = opaque(map(t1));
    const ColoredVertex a{{left, y0, 0}, c0}, b{{right, y0, 0}, c1}, c{{right, y1, 0}, c1}, d{{left, y1, 0}, c0};
    triangle(triangles_, a, b, c);
    triangle(triangles_, a, c, d);
  }
}

void ScreenCanvas::disc(float cx, float cy, float radius, const Eigen::Vector4f& colour) {
  constexpr int kSegments = 16;
  const ColoredVertex centre{{cx, cy, 0}, colour};
  for (int i = 0; i < kSegments; ++i) {
    const float a0 = 2 * std::numbers::pi_v<float> * i / kSegments, a1 = 2 * std::numbers::pi_v<float> * (i + 1) / kSegments;
    triangle(triangles_, centre, {{cx + radius * std::cos(a0), cy + radius * std::sin(a0), 0}, colour},
             {{cx + radius * std::cos(a1), cy + radius * std::sin(a1), 0}, colour});
  }
}

void ScreenCanvas::text(float x, float y, std::string_view text, const Eigen::Vector4f& colour) {
  const float s = unit();
  for (const char c : text) {
    const auto& rows = glyph(c);
    const auto lit = [&](int row, int col) { return col < kGlyphWidth && (rows[row] & (0x10 >> col)); };
    for (int row = 0; row < kGlyphHeight; ++row)
      for (int col = 0; col < kGlyphWidth; ++col) {
        if (!lit(row, col)) continue;
        const int begin = col;  // one rectangle per run of lit pixels
        while (lit(row, col + 1)) ++col;
        rect(x + begin * s, y + row * s, x + (col + 1) * s, y + (row + 1) * s, colour);
      }
    x += kGlyphAdvance * s;
  }
}

float ScreenCanvas::textWidth(std::string_view text) const { return float(hdprior::textWidth(text, fontScale_)); }

float ScreenCanvas::capHeight() const { return float(hdprior::capHeight(fontScale_)); }

Eigen::Matrix4f ScreenCanvas::projection() const { return orthographic(0.0f, float(width_), float(height_), 0.0f, -1.0f, 1.0f); }

}  // namespace hdprior::render
