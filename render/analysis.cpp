#include "render/analysis.h"

#include <cmath>
#include <limits>
#include <utility>

#include "engine/changes/change_events.h"
#include "engine/changes/map_change_report.h"
#include "engine/eval/missed_change_events.h"
#include "engine/error.h"
#include "engine/pipeline/session.h"

namespace hdprior::render {
namespace {

// Per pose: the distance to the ground truth at its timestamp (ATE translation, city frame,
// no alignment: the pipeline starts from the first true pose); NaN where the truth has no pose.
std::vector<double> translationErrors(const PoseTrajectory& truth, const PoseTrajectory& estimate) {
  std::vector<double> errors;
  errors.reserve(estimate.size());
  for (size_t i = 0; i < estimate.size(); ++i) {
    const int64_t t = estimate.timestamps()[i];
    errors.push_back(truth.covers(t) ? (truth.at(t).translation() - estimate.poses()[i].translation()).norm()
                                     : std::numeric_limits<double>::quiet_NaN());
  }
  return errors;
}

// Per-pose errors spread over the log's sweeps: NaN at the sweeps the run skipped (unreadable).
std::vector<double> perSweep(std::vector<double> errors, const std::vector<SkippedSweep>& skipped) {
  for (const SkippedSweep& s : skipped) {  // in increasing index
    if (s.index <= errors.size()) errors.insert(errors.begin() + long(s.index), std::numeric_limits<double>::quiet_NaN());
  }
  return errors;
}

}  // namespace

void setMapChanges(Analysis& analysis, std::shared_ptr<const MapChangeReport> report,
                   std::optional<std::vector<MapChangeLabel>> labels, const std::vector<int64_t>& sweepTimestamps) {
  std::vector<RunEvent> run;
  for (const RunEvent& e : analysis.events)
    if (!isMapCheckEvent(e.kind)) run.push_back(e);
  std::vector<RunEvent> check = mapChangeEvents(*report);
  if (labels) {
    check = mergedEvents(check, missedChangeEvents(*report, *labels, finalTrajectory(analysis), sweepTimestamps));
  }
  analysis.events = mergedEvents(run, check);
  analysis.changes = std::move(report);
  analysis.changeLabels = std::move(labels);
}

void setMapChanges(Analysis& analysis, MapChangeReport report, std::optional<std::vector<MapChangeLabel>> labels,
                   const std::vector<int64_t>& sweepTimestamps) {
  setMapChanges(analysis, std::make_shared<const MapChangeReport>(std::move(report)), std::move(labels), sweepTimestamps);
}

Analysis analysisOf(const Session& session) {
  Analysis a;
  a.groundTruth = session.groundTruth();
  a.odometry = session.odometryTrajectory();
  a.optimized = session.optimizedTrajectory();
  a.odometryError = perSweep(translationErrors(a.groundTruth, a.odometry), session.skippedSweeps());
  if (session.givenOdometry()) a.odometryFile = session.givenOdometry()->file;
  if (!a.optimized.empty()) a.optimizedError = perSweep(translationErrors(a.groundTruth, a.optimized), session.skippedSweeps());
  const std::vector<SE3> poses = session.keyframePoses();
  const auto& keyframes = session.odometry().keyframes();
  for (size_t k = 0; k < keyframes.size() && k < poses.size(); ++k)
    a.keyframes.push_back({.keyframe = k, .frame = session.sweepOfFrame(keyframes[k].frame), .pose = poses[k], .constraint = std::nullopt});
  for (const KeyframeMatch& m : session.matches())
    if (m.keyframe < a.keyframes.size()) a.keyframes[m.keyframe].constraint = constraintOf(m);
  a.diagnostics = keyframeDiagnostics(session.matches(), poses, session.groundTruth(),
                                      [&](size_t f) { return session.sweepOfFrame(f); });
  a.events = runEvents(a.diagnostics, session.skippedSweeps());
  return a;
}

Comparison comparisonOf(const Session& session, std::string name) {
  Analysis a = analysisOf(session);
  const bool priors = !a.optimized.empty();
  return {.name = std::move(name), .optimized = priors ? std::move(a.optimized) : std::move(a.odometry),
          .optimizedError = priors ? std::move(a.optimizedError) : std::move(a.odometryError),
          .diagnostics = std::move(a.diagnostics), .inspection = std::nullopt, .landscape = std::nullopt};
}

void setFileTrajectory(Analysis& analysis, const PoseTrajectory& truth, PoseTrajectory file, std::string name) {
  analysis.fileError = translationErrors(truth, file);
  analysis.file = std::move(file);
  analysis.fileName = std::move(name);
}

void inspect(Analysis& analysis, const Session& session, const HdMap& map, size_t k) {
  const Config& config = session.config();
  analysis.inspection = session.inspectKeyframe(k, config.roadPoints, config.match);
  if (analysis.inspection->roadPoints.empty()) throw Error("keyframe " + std::to_string(k), "has no road points");
  analysis.landscape = matchLandscape(map, config.match, analysis.inspection->roadPoints, analysis.inspection->match.estimate);
}

}  // namespace hdprior::render
