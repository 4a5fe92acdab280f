#pragma once

namespace hdprior::ui {
class AppState;

// Colour bars with their ranges: the ground-height raster (terrain ramp, city z) and the
// sweep colouring (Turbo).
void drawHeightLegend(AppState& state);

}  // namespace hdprior::ui
