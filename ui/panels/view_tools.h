#pragma once

namespace hdprior::ui {
class AppState;

// The 3-D view's tools under the mouse: Measure (M: two clicks on the ground give the distance
// along and across the ego heading; Esc leaves) and Pick (P: the tooltip names the sweep point,
// drivable-area polygon and NDT cell under the cursor; a click keeps it in the status line).
void handleViewTools(AppState& state);
// The tools' tooltip and hint; after the panels so that it stays on top.
void drawViewTools(AppState& state);

}  // namespace hdprior::ui
