#pragma once
#include <functional>

#include <Eigen/Core>

#include "render/overlays/screen_canvas.h"

namespace hdprior::render {

// One box of the view's overlay (a colour bar, the scale bar, the legend): its size in pixels, so
// the overlay can stack boxes in a corner, and how to draw it with its top-left corner at a point.
struct OverlayBlock {
  Eigen::Vector2f size = Eigen::Vector2f::Zero();
  std::function<void(ScreenCanvas&, const Eigen::Vector2f& topLeft)> draw;
};

// The overlay's text colour.
inline const Eigen::Vector4f kOverlayText{0.92f, 0.92f, 0.92f, 1.0f};

}  // namespace hdprior::render
