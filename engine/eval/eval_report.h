#pragma once
#include <string>
#include <vector>

#include "engine/eval/eval_summary.h"
#include "engine/eval/rgb_image.h"

namespace hdprior {

// The files `hdprior eval` writes, as text (CSV per RFC 4180) or an image; the caller writes them.

// per_log.csv: one row per log, in the given order; a failed log has only its id, path and error.
// `sweeps` counts the sweeps mapped, `skipped_sweeps` those left out as unreadable.
// Figures not available (no optimised trajectory, a path shorter than an RPE segment) are empty.
std::string perLogCsv(const std::vector<LogEvaluation>& logs);

// table.md / table.csv: the paper's table, a row per trajectory (odometry, with HD-map priors),
// columns mean / median / rmse / std / max (metres) averaged over the logs that went through. When
// none did, table.md says so and shows n/a; table.csv leaves those fields empty (missing values).
std::string summaryMarkdown(const EvalSummary& summary);
std::string summaryCsv(const EvalSummary& summary);

// rmse_boxplot.png: the per-log ATE RMSE of the successful logs, a box for the odometry and one
// for the optimised trajectories when there are any.
RgbImage rmseBoxPlot(const std::vector<LogEvaluation>& logs);

}  // namespace hdprior
