#pragma once

namespace hdprior::ui {
class AppState;

// Every layer with its visibility, opacity and own options (drawn from Layer::options(), so a
// new layer needs no code here), and the camera controls.
void drawLayersPanel(AppState& state);

}  // namespace hdprior::ui
