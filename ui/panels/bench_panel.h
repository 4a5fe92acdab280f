#pragma once

namespace hdprior::ui {
class AppState;

// The tuning bench on the right: tabs Pipeline (run / step / cancel), NDT (matcher parameters, match
// this keyframe, cost landscape), PGO (optimise now), Keyframe (inspector), Events (events and
// bookmarks), Compare (run B, A against B) and Export.
void drawBenchPanel(AppState& state);

// Each tab's contents (one file each).
void drawPipelineTab(AppState& state);
void drawNdtTab(AppState& state);
void drawPgoTab(AppState& state);
void drawKeyframeTab(AppState& state);
void drawEventsTab(AppState& state);
void drawCompareTab(AppState& state);
void drawExportTab(AppState& state);

}  // namespace hdprior::ui
