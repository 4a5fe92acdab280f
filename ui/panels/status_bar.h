#pragma once

namespace hdprior::ui {
class AppState;

// FPS, points drawn, the ego pose and the ground point under the mouse with its height.
void drawStatusBar(AppState& state);

}  // namespace hdprior::ui
