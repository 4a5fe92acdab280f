#pragma once
#include <imgui.h>

#include <vector>

#include "engine/pipeline/diagnostic_plots.h"

namespace hdprior::ui {
class AppState;

// One run's rows in a diagnostic plot and how its lines look (the A/B comparison draws two).
struct DiagnosticRun {
  const std::vector<KeyframeDiagnostic>* rows;
  const char* name;  // "A", "B"; shown in the hover
  bool dashed = false;
};

// A time plot of one diagnostic over the log in [min, max]: the plot's series as lines with gaps
// where a value is missing, its threshold as a red line, a marker per keyframe in its status colour,
// the playhead; hovering shows the keyframe's values, a click selects and matches that keyframe.
void drawDiagnosticPlot(AppState& state, const DiagnosticPlot& plot, const std::vector<DiagnosticRun>& runs, ImVec2 min,
                        ImVec2 max);

}  // namespace hdprior::ui
