#pragma once
// Where the panels sit in the window (pixels): layers on the left, the bench on the right, plots,
// timeline and status bar at the bottom, legend left of the bench; the 3-D view shows through around them.
namespace hdprior::ui {

inline constexpr float kLayersPanelWidth = 310.0f;
inline constexpr float kTimelineHeight = 62.0f;
inline constexpr float kStatusBarHeight = 26.0f;
inline constexpr float kLegendWidth = 250.0f;
inline constexpr float kBenchPanelWidth = 360.0f;  // the tuning bench, on the right
inline constexpr float kPlotsHeight = 170.0f;       // the error plot, above the timeline

}  // namespace hdprior::ui
