#pragma once

namespace hdprior::ui {
class AppState;

// ATE per frame of the odometry and the optimised trajectory, with a cursor at the current frame (a
// click goes to that frame), and below it the Diagnostics plots the user picked (the "plots" menu),
// all sharing the timeline's playhead.
void drawPlotsPanel(AppState& state);

}  // namespace hdprior::ui
