#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "engine/eval/change_score.h"
#include "engine/eval/match_calibration.h"
#include "engine/eval/trajectory_errors.h"

namespace hdprior {

// One log of a batch evaluation (`hdprior eval`): its evaluations, or the error that stopped it.
struct LogEvaluation {
  std::string id;
  std::filesystem::path path;
  size_t sweeps = 0;
  std::vector<std::string> skippedSweeps;  // "<sweep file>: <problem>" of each sweep the run left out
  std::optional<TrajectoryEvaluation> odometry;
  std::optional<TrajectoryEvaluation> optimized;  // with priors
  size_t matchesAccepted = 0, matchesDegenerate = 0, matchesRejected = 0;
  std::vector<MatchErrorSample> priorErrors;  // the priors the graph used, against the truth
  double pipelineSeconds = 0;
  // With `eval --check-map`: the map check's score (every report a false alarm when the log has no
  // map_change.json; `labelled` when it has one).
  struct MapCheck {
    ChangeScore score;      // drivable areas
    ChangeScore crossings;  // pedestrian crossings
    ChangeScore laneLines;  // painted lane lines
    bool labelled = false;
  };
  std::optional<MapCheck> mapCheck;
  std::string error;  // empty when the log went through

  bool ok() const { return error.empty(); }
};

// The paper's table over a batch: each ATE statistic (mean, median, rmse, std, max) is the average
// over the logs that went through of that log's per-sweep statistic; `count` is how many logs.
struct EvalSummary {
  // The ATE RMSE along and across the road, each the average over the logs of that log's RMSE.
  struct RoadSplit {
    double along = 0, lateral = 0;
  };
  size_t logs = 0, failed = 0;
  ErrorStats odometry;
  std::optional<ErrorStats> optimized;  // when any successful log has an optimised trajectory
  RoadSplit odometrySplit, optimizedSplit;
  // With priors: every log's priors pooled, and the logs whose ATE RMSE the priors made more than
  // 10 % worse than the odometry's (the largest optimised / odometry ratio among all).
  MatchCalibration priors;
  size_t logsWorse = 0;
  double worstRatio = 0.0;
  // The map checks summed over the logs with labelled changes and over those without.
  struct MapCheckSum {
    ChangeScore drivableAreas, crossings, laneLines;
    size_t logs = 0;
  };
  std::optional<MapCheckSum> mapCheckLabelled, mapCheckUnlabelled;
};
EvalSummary summarizeLogs(const std::vector<LogEvaluation>& logs);

}  // namespace hdprior
