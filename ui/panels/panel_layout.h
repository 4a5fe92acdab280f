#pragma once
// Where the panels sit in the window (pixels): layers on the left, the bench on the right, plots,
// timeline and status bar at the bottom; the 3-D view shows through around them, with its overlay
// (colour bars, scale bar, marker legend) in the part they leave free.
#include <cstddef>

#include "render/overlays/view_overlay.h"

namespace hdprior::ui {

inline constexpr float kLayersPanelWidth = 310.0f;
inline constexpr float kTimelineHeight = 62.0f;
inline constexpr float kStatusBarHeight = 26.0f;
inline constexpr float kBenchPanelWidth = 360.0f;  // the tuning bench, on the right
inline constexpr float kPlotsHeight = 170.0f;       // the error plot, above the timeline
inline constexpr float kDiagnosticRowHeight = 96.0f;  // a row of two diagnostic plots below it

// The plots panel with `diagnostics` diagnostic plots shown, two to a row.
inline float plotsPanelHeight(size_t diagnostics) { return kPlotsHeight + kDiagnosticRowHeight * float((diagnostics + 1) / 2); }

// The view's edges the panels cover, in framebuffer pixels (`scale` of them per window pixel).
inline render::ScreenInsets viewInsets(float scale, size_t diagnostics) {
  return {scale * kLayersPanelWidth, 0.0f, scale * kBenchPanelWidth,
          scale * (kStatusBarHeight + kTimelineHeight + plotsPanelHeight(diagnostics))};
}

}  // namespace hdprior::ui
