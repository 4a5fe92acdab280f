#pragma once

namespace hdprior::ui {
class AppState;

// Mouse and keyboard not taken by a panel: camera (drag orbit/pan, wheel zoom, T top-down,
// F follow, W/A/S/D move, Q/E turn, +/- zoom, R reset) and timeline (Left/Right step, Space
// play, Home/End). Call between ImGui::NewFrame and the panels. viewportHeight in pixels.
void handleViewInput(AppState& state, float viewportHeight);

}  // namespace hdprior::ui
