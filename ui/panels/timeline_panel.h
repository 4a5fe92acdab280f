#pragma once

namespace hdprior::ui {
class AppState;

// Frame slider, step and play/pause buttons, playback speed, frame and timestamp readout.
void drawTimelinePanel(AppState& state);

}  // namespace hdprior::ui
