#pragma once
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "render/gpu_mesh.h"

namespace hdprior::render {

// Flat shapes and text in viewport pixels (x right, y down from the top-left corner), for what is
// drawn over the 3-D view. Text uses the figures' bitmap font (engine/eval/bitmap_font.h), each
// font pixel a fontScale x fontScale square, so it stays crisp. Only collects triangles: the
// overlay uploads and draws them in one call.
class ScreenCanvas {
 public:
  ScreenCanvas(int width, int height, int fontScale);

  int width() const { return width_; }
  int height() const { return height_; }
  // The unit every overlay size is a multiple of: one font pixel.
  float unit() const { return float(fontScale_); }

  void rect(float x0, float y0, float x1, float y1, const Eigen::Vector4f& colour);
  // The colour map from t = 0 at x0 to t = 1 at x1.
  void ramp(float x0, float y0, float x1, float y1, Eigen::Vector3f (*map)(float), int steps = 64);
  void disc(float cx, float cy, float radius, const Eigen::Vector4f& colour);
  // `text` with the top of its capitals at y.
  void text(float x, float y, std::string_view text, const Eigen::Vector4f& colour);
  float textWidth(std::string_view text) const;
  float capHeight() const;

  // Viewport pixels to clip space.
  Eigen::Matrix4f projection() const;
  const std::vector<ColoredVertex>& triangles() const { return triangles_; }

 private:
  int width_, height_, fontScale_;
  std::vector<ColoredVertex> triangles_;
};

}  // namespace hdprior::render
