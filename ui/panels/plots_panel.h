#pragma once

namespace hdprior::ui {
class AppState;

// ATE per frame of the odometry and the optimised trajectory, with a cursor at the current frame;
// a click on the plot goes to that frame.
void drawPlotsPanel(AppState& state);

}  // namespace hdprior::ui
