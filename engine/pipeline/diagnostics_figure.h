#pragma once
#include <string>
#include <vector>

#include "engine/eval/rgb_image.h"
#include "engine/pipeline/diagnostic_plots.h"
#include "engine/pipeline/keyframe_diagnostics.h"

namespace hdprior {

// One run's keyframe diagnostics under the name the figure gives it (its folder's name).
struct DiagnosticsRun {
  std::string name;
  std::vector<KeyframeDiagnostic> rows;
};

struct DiagnosticsFigureOptions {
  int width = 1280;
  int panelHeight = 150;  // each plot's area, without its title row
};

// The colour of a run's line (run 0: A, 1: B) of a plot's series (0: the first, 1: the second), and
// of the threshold line.
Rgb diagnosticsLineColour(size_t run, size_t series);
inline constexpr Rgb kDiagnosticsThresholdColour{220, 30, 30};

// Every plot with a finite value in one of the runs, in diagnosticPlots() order.
std::vector<const DiagnosticPlot*> plotsWithValues(const std::vector<DiagnosticsRun>& runs);

// `hdprior plot`'s figure on a white background: a header naming the run (with a second run: "A:
// <name>" and "B: <name>" in their line colours) and the markers' status colours, a strip per run with
// a tick per keyframe in its status colour, then one panel per
// plot stacked over a shared x axis, the frame (the log's sweep index). Each panel has its title with
// the unit, y ticks, a line per series with gaps where a value is missing, markers on its first
// series coloured by the keyframe's status (constraint_colour.h) and the plot's threshold (the gate's
// quantile under the chi2) as a red line.
RgbImage drawDiagnosticsFigure(const std::vector<DiagnosticsRun>& runs, const std::vector<const DiagnosticPlot*>& plots,
                               const DiagnosticsFigureOptions& options = {});

}  // namespace hdprior
