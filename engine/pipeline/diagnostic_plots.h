#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/pipeline/keyframe_diagnostics.h"

namespace hdprior {

// One time plot of the debugging bench (and of `hdprior plot`): the keyframe diagnostics it draws
// as lines, and the one it draws as a threshold (the gate's quantile under the innovation chi2).
struct DiagnosticPlot {
  struct Series {
    DiagnosticField field;
    const char* label;
  };
  const char* name;   // the script's and --plots' name: "score", "sigma_lateral", ...
  const char* title;  // with the unit
  std::vector<Series> series;
  std::optional<DiagnosticField> threshold;
};

// Every plot, in the order the bench lists them.
const std::vector<DiagnosticPlot>& diagnosticPlots();
// The plot so named, or nullptr.
const DiagnosticPlot* findDiagnosticPlot(std::string_view name);
// "score, inliers, ..." for messages.
std::string diagnosticPlotNames();
// The plots a comma-separated list names ("chi2,sigma_lateral"), in its order, each once; throws
// Error(`where`, ...) for an unknown or empty name.
std::vector<const DiagnosticPlot*> parseDiagnosticPlotList(std::string_view list, const std::string& where);

}  // namespace hdprior
