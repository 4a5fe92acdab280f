#include "engine/eval/eval_report.h"

#include <cstdio>
#include <functional>
#include <numbers>

#include "engine/eval/box_plot.h"

namespace hdprior {
namespace {

constexpr const char* kOptimizedName = "with HD-map priors";

std::string number(double v, int decimals = 6) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string quoted = "\"";
  for (char c : s) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csvRow(const std::vector<std::string>& fields) {
  std::string row;
  for (size_t i = 0; i < fields.size(); ++i) row += (i ? "," : "") + csvField(fields[i]);
  return row + "\n";
}

std::string rpeField(const RpeResult& r) { return r.segments ? number(r.translationPercent) : ""; }

// The nine columns of one trajectory, or empty fields.
void appendTrajectory(std::vector<std::string>& row, const std::optional<TrajectoryEvaluation>& e) {
  if (!e) {
    row.insert(row.end(), 9, "");
    return;
  }
  const ErrorStats& t = e->ate.translation;
  for (double v : {t.mean, t.median, t.rmse, t.std, t.max, e->ate.along.rmse, e->ate.lateral.rmse}) row.push_back(number(v));
  row.push_back(rpeField(e->rpe10));
  row.push_back(rpeField(e->rpe100));
}

std::string averagingLine(const EvalSummary& s) {
  const size_t ok = s.logs - s.failed;
  if (ok == 0) {
    return "No log went through (" + std::to_string(s.failed) + " of " + std::to_string(s.logs) +
           " failed; per_log.csv has each one's error): there is nothing to average (n/a).";
  }
  return "ATE (m, city frame, every run starting at the first ground-truth pose): each column is the average over the " +
         std::to_string(ok) + (ok == 1 ? " log" : " logs") + " that went through (of " + std::to_string(s.logs) + "; " +
         std::to_string(s.failed) + " failed) of that log's per-sweep statistic.";
}

void appendDirection(std::vector<std::string>& row, const DirectionCalibration& d, double unit) {
  if (d.observed == 0) {
    row.insert(row.end(), 3, "");
    return;
  }
  row.push_back(number(d.rms * unit));
  row.push_back(number(d.beyond3Sigma));
  row.push_back(number(d.medianNees));
}

std::string calibrationMarkdown(const EvalSummary& s) {
  const size_t ok = s.logs - s.failed;
  std::string md = "\nPriors the graph used, pooled over the " + std::to_string(ok) + (ok == 1 ? " log" : " logs") + " (" +
                   std::to_string(s.priors.matches) +
                   " priors; error against the ground truth in the true vehicle frame; NEES = (error / reported sigma)^2, "
                   "0.45 median and 0.27 % beyond 3 sigma for an honest Gaussian; a direction a prior reports "
                   "unobservable is left out):\n\n| direction | observed | rms | beyond 3 sigma | median NEES |\n"
                   "|---|---:|---:|---:|---:|\n";
  const auto line = [&](const char* name, const DirectionCalibration& d, double unit, const char* u) {
    md += std::string("| ") + name + " | " + std::to_string(d.observed) + " | " + number(d.rms * unit, 3) + " " + u + " | " +
          number(100.0 * d.beyond3Sigma, 1) + " % | " + number(d.medianNees, 2) + " |\n";
  };
  line("along", s.priors.along, 1.0, "m");
  line("lateral", s.priors.lateral, 1.0, "m");
  line("yaw", s.priors.yaw, 180.0 / std::numbers::pi, "deg");
  md += "\nLogs whose ATE RMSE with priors is more than 10 % above the odometry's: " + std::to_string(s.logsWorse) +
        " (largest ratio " + number(s.worstRatio, 2) + ").\n";
  return md;
}

using RowFunction = std::function<void(const char*, const ErrorStats&, const EvalSummary::RoadSplit&)>;
void forEachRow(const EvalSummary& s, const RowFunction& fn) {
  fn("odometry", s.odometry, s.odometrySplit);
  if (s.optimized) fn(kOptimizedName, *s.optimized, s.optimizedSplit);
}

}  // namespace

std::string perLogCsv(const std::vector<LogEvaluation>& logs) {
  std::vector<std::string> header = {"log_id", "path", "sweeps", "skipped_sweeps", "path_length_m"};
  for (const char* t : {"odometry", "optimized"}) {
    for (const char* c : {"ate_mean_m", "ate_median_m", "ate_rmse_m", "ate_std_m", "ate_max_m", "along_rmse_m", "lateral_rmse_m",
                          "rpe10_percent", "rpe100_percent"}) {
      header.push_back(std::string(t) + "_" + c);
    }
  }
  for (const char* c : {"matches_accepted", "matches_degenerate", "matches_rejected", "prior_lateral_rms_m",
                        "prior_lateral_beyond_3sigma", "prior_lateral_median_nees", "prior_yaw_rms_deg",
                        "prior_yaw_beyond_3sigma", "prior_yaw_median_nees", "pipeline_s", "error"}) {
    header.push_back(c);
  }
  std::string csv = csvRow(header);
  for (const LogEvaluation& log : logs) {
    std::vector<std::string> row = {log.id, log.path.string()};
    if (!log.ok()) {
      row.resize(header.size() - 1);
      row.push_back(log.error);
      csv += csvRow(row);
      continue;
    }
    row.push_back(std::to_string(log.sweeps));
    row.push_back(std::to_string(log.skippedSweeps.size()));
    row.push_back(log.odometry ? number(log.odometry->pathLength, 3) : "");
    appendTrajectory(row, log.odometry);
    appendTrajectory(row, log.optimized);
    if (log.optimized) {
      for (size_t n : {log.matchesAccepted, log.matchesDegenerate, log.matchesRejected}) row.push_back(std::to_string(n));
      const MatchCalibration c = calibrateMatches(log.priorErrors);
      appendDirection(row, c.lateral, 1.0);
      appendDirection(row, c.yaw, 180.0 / std::numbers::pi);
    } else {
      row.insert(row.end(), 9, "");
    }
    row.push_back(number(log.pipelineSeconds, 2));
    row.push_back("");
    csv += csvRow(row);
  }
  return csv;
}

namespace {

// The map checks of `eval --check-map`: recall and precision where the logs label their map's
// changes, false alarms per km where they do not.
std::string mapCheckMarkdown(const EvalSummary& s) {
  std::string md;
  char b[400];
  const auto ratio = [](size_t of, double v) { return of ? number(v, 2) : std::string("n/a"); };
  if (const auto& m = s.mapCheckLabelled) {
    const ChangeScore& c = m->drivableAreas;
    std::snprintf(b, sizeof b,
                  "\nMap check on %zu logs with labelled map changes (drivable areas; 5 m, 15 m from the drive): %zu of %zu changes "
                  "found (recall %s), %zu of %zu reports near a change (precision %s), %.2f false alarms per km over %.2f km.\n",
                  m->logs, c.changesFound, c.changes, ratio(c.changes, c.recall()).c_str(), c.reportsNearChange,
                  c.reports, ratio(c.reports, c.precision()).c_str(),
                  c.drivenKm > 0 ? double(c.falseAlarms()) / c.drivenKm : 0.0, c.drivenKm);
    md += b;
  }
  if (const auto& m = s.mapCheckUnlabelled) {
    const ChangeScore& c = m->drivableAreas;
    std::snprintf(b, sizeof b, "\nMap check on %zu logs without labelled changes: %zu reports (each a false alarm on a current map) over %.2f km, %.2f per km.\n",
                  m->logs, c.reports, c.drivenKm, c.drivenKm > 0 ? double(c.reports) / c.drivenKm : 0.0);
    md += b;
  }
  const auto labelled = [&](const char* what, const ChangeScore& c) {
    std::snprintf(b, sizeof b,
                  "\n%s, the same logs with labelled changes: %zu of %zu changes found (recall %s), %zu of %zu reports near a change "
                  "(precision %s).\n",
                  what, c.changesFound, c.changes, ratio(c.changes, c.recall()).c_str(), c.reportsNearChange, c.reports,
                  ratio(c.reports, c.precision()).c_str());
    md += b;
  };
  const auto unlabelled = [&](const char* what, const ChangeScore& c) {
    std::snprintf(b, sizeof b, "\n%s, the logs without labelled changes: %zu reports, %.2f per km.\n", what, c.reports,
                  c.drivenKm > 0 ? double(c.reports) / c.drivenKm : 0.0);
    md += b;
  };
  if (const auto& m = s.mapCheckLabelled) {
    labelled("Crossings (paint within 12 m of the lidar)", m->crossings);
    labelled("Lane lines (paint within 8 m of the lidar; a report is a line with contradicted stretches)", m->laneLines);
  }
  if (const auto& m = s.mapCheckUnlabelled) {
    unlabelled("Crossings", m->crossings);
    unlabelled("Lane lines", m->laneLines);
  }
  return md;
}

}  // namespace

std::string summaryMarkdown(const EvalSummary& s) {
  std::string md = averagingLine(s) +
                   " Along and lateral: the rmse of the error along and across the true heading (the drivable area "
                   "observes the lateral part; along the road only at junctions and curves).\n\n"
                   "| trajectory | logs | mean | median | rmse | std | max | along rmse | lateral rmse |\n"
                   "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  forEachRow(s, [&](const char* name, const ErrorStats& e, const EvalSummary::RoadSplit& split) {
    md += std::string("| ") + name + " | " + std::to_string(e.count);
    for (double v : {e.mean, e.median, e.rmse, e.std, e.max, split.along, split.lateral}) md += " | " + (e.count ? number(v, 3) : "n/a");
    md += " |\n";
  });
  if (s.optimized) md += calibrationMarkdown(s);
  md += mapCheckMarkdown(s);
  return md;
}

std::string summaryCsv(const EvalSummary& s) {
  std::string csv = csvRow({"trajectory", "logs", "failed_logs", "mean_m", "median_m", "rmse_m", "std_m", "max_m",
                            "along_rmse_m", "lateral_rmse_m", "averaging"});
  forEachRow(s, [&](const char* name, const ErrorStats& e, const EvalSummary::RoadSplit& split) {
    // Over no log there is no average: empty fields, which CSV readers take as missing values.
    const auto stat = [&](double v) { return e.count ? number(v) : std::string(); };
    csv += csvRow({name, std::to_string(e.count), std::to_string(s.failed), stat(e.mean), stat(e.median), stat(e.rmse),
                   stat(e.std), stat(e.max), stat(split.along), stat(split.lateral),
                   e.count ? "mean over logs of each log's per-sweep ATE statistic" : "no log went through"});
  });
  return csv;
}

RgbImage rmseBoxPlot(const std::vector<LogEvaluation>& logs) {
  BoxPlotSeries odometry{"odometry", {}, {230, 120, 30}}, optimized{kOptimizedName, {}, {40, 100, 200}};
  for (const LogEvaluation& log : logs) {
    if (!log.ok()) continue;
    if (log.odometry) odometry.values.push_back(log.odometry->ate.translation.rmse);
    if (log.optimized) optimized.values.push_back(log.optimized->ate.translation.rmse);
  }
  std::vector<BoxPlotSeries> series = {odometry};
  if (!optimized.values.empty()) series.push_back(optimized);
  return drawBoxPlot(series, {.title = "ATE RMSE per log", .yTitle = "ATE RMSE (m)"});
}

}  // namespace hdprior
