#pragma once
// Where the panels sit in the window (pixels): layers on the left, timeline and status bar at
// the bottom, legend top right; the 3-D view shows through around them.
namespace hdprior::ui {

inline constexpr float kLayersPanelWidth = 310.0f;
inline constexpr float kTimelineHeight = 62.0f;
inline constexpr float kStatusBarHeight = 26.0f;
inline constexpr float kLegendWidth = 250.0f;

}  // namespace hdprior::ui
