#include "engine/eval/eval_summary.h"

#include <algorithm>

namespace hdprior {
namespace {

void accumulate(ErrorStats& sum, const ErrorStats& s) {
  ++sum.count;
  sum.mean += s.mean;
  sum.median += s.median;
  sum.rmse += s.rmse;
  sum.std += s.std;
  sum.max += s.max;
}

void accumulate(EvalSummary::RoadSplit& sum, const AteResult& ate) {
  sum.along += ate.along.rmse;
  sum.lateral += ate.lateral.rmse;
}

EvalSummary::RoadSplit averaged(EvalSummary::RoadSplit sum, size_t count) {
  if (count == 0) return sum;
  return {sum.along / double(count), sum.lateral / double(count)};
}

ErrorStats averaged(ErrorStats sum) {
  if (sum.count == 0) return sum;
  const double n = double(sum.count);
  sum.mean /= n;
  sum.median /= n;
  sum.rmse /= n;
  sum.std /= n;
  sum.max /= n;
  return sum;
}

}  // namespace

EvalSummary summarizeLogs(const std::vector<LogEvaluation>& logs) {
  EvalSummary s;
  s.logs = logs.size();
  ErrorStats odometry, optimized;
  std::vector<MatchErrorSample> priors;
  for (const LogEvaluation& log : logs) {
    if (!log.ok()) {
      ++s.failed;
      continue;
    }
    if (log.odometry) {
      accumulate(odometry, log.odometry->ate.translation);
      accumulate(s.odometrySplit, log.odometry->ate);
    }
    if (log.optimized) {
      accumulate(optimized, log.optimized->ate.translation);
      accumulate(s.optimizedSplit, log.optimized->ate);
    }
    priors.insert(priors.end(), log.priorErrors.begin(), log.priorErrors.end());
    if (log.mapCheck) {
      std::optional<EvalSummary::MapCheckSum>& sum = log.mapCheck->labelled ? s.mapCheckLabelled : s.mapCheckUnlabelled;
      if (!sum) sum.emplace();
      sum->drivableAreas += log.mapCheck->score;
      sum->crossings += log.mapCheck->crossings;
      sum->laneLines += log.mapCheck->laneLines;
      ++sum->logs;
    }
    if (log.odometry && log.optimized && log.odometry->ate.translation.rmse > 0.0) {
      const double ratio = log.optimized->ate.translation.rmse / log.odometry->ate.translation.rmse;
      s.worstRatio = std::max(s.worstRatio, ratio);
      s.logsWorse += ratio > 1.1;
    }
  }
  s.priors = calibrateMatches(priors);
  s.odometry = averaged(odometry);
  s.odometrySplit = averaged(s.odometrySplit, odometry.count);
  s.optimizedSplit = averaged(s.optimizedSplit, optimized.count);
  if (optimized.count > 0) s.optimized = averaged(optimized);
  return s;
}

}  // namespace hdprior
