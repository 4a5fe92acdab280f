#pragma once
// Where the panels sit in the window (pixels): layers on the left, the bench on the right, plots,
// timeline and status bar at the bottom; the 3-D view shows through around them, with its overlay
// (colour bars, scale bar, marker legend) in the part they leave free.
#include "render/overlays/view_overlay.h"

namespace hdprior::ui {

inline constexpr float kLayersPanelWidth = 310.0f;
inline constexpr float kTimelineHeight = 62.0f;
inline constexpr float kStatusBarHeight = 26.0f;
inline constexpr float kBenchPanelWidth = 360.0f;  // the tuning bench, on the right
inline constexpr float kPlotsHeight = 170.0f;       // the error plot, above the timeline

// The view's edges the panels cover, in framebuffer pixels (`scale` of them per window pixel).
inline render::ScreenInsets viewInsets(float scale) {
  return {scale * kLayersPanelWidth, 0.0f, scale * kBenchPanelWidth,
          scale * (kStatusBarHeight + kTimelineHeight + kPlotsHeight)};
}

}  // namespace hdprior::ui
