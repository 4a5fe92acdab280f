#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/eval/map_change_labels.h"
#include "engine/geom/ground_measure.h"
#include "engine/geom/pose_trajectory.h"
#include "engine/match/cost_landscape.h"
#include "engine/match/match_result.h"
#include "engine/pipeline/keyframe_diagnostics.h"
#include "engine/pipeline/keyframe_inspection.h"
#include "engine/pipeline/prior_constraint.h"
#include "engine/pipeline/run_events.h"

namespace hdprior {
class HdMap;
class Session;
struct MapChangeReport;
}

namespace hdprior::render {

// A keyframe along the trajectory, at its final pose, with what its match did.
struct KeyframeMark {
  size_t keyframe = 0, frame = 0;
  SE3 pose = SE3::Identity();
  std::optional<PriorConstraint> constraint;  // as the graph took it; none: odometry only
};

// Run B of an A/B comparison: the same log with another configuration, run in the background.
struct Comparison {
  std::string name;                                    // the configuration's file name, or "bench parameters"
  PoseTrajectory optimized;                            // its final trajectory (the odometry's without priors)
  std::vector<double> optimizedError;                  // ATE translation per sweep, as Analysis::optimizedError
  std::vector<KeyframeDiagnostic> diagnostics;
  std::optional<KeyframeInspection> inspection;        // B's match of the keyframe A inspects
  std::optional<CostLandscape> landscape;              // around B's estimate
};

// What the pipeline and the tuning bench computed, for the analysis layers to draw (trajectories,
// keyframes, the selected keyframe's points, match and cost landscape). Plain data; the app and
// `hdprior snapshot` fill it from a Session.
struct Analysis {
  PoseTrajectory groundTruth, odometry, optimized;     // city_T_ego; empty when not computed
  std::vector<double> odometryError, optimizedError;   // ATE translation per sweep done of odometry / optimized
                                                       // (NaN: no truth, or a sweep skipped as unreadable)
  std::string odometryFile;                            // the run's odometry came from this trajectory file; empty: built-in
  // A trajectory file opened as the odometry (before or without a run over it): city_T_ego at every
  // sweep, anchored as a run anchors it, and its ATE translation per sweep.
  PoseTrajectory file;
  std::vector<double> fileError;
  std::string fileName;
  std::vector<KeyframeMark> keyframes;
  std::vector<KeyframeDiagnostic> diagnostics;         // one per matched keyframe
  std::vector<RunEvent> events;
  std::optional<KeyframeInspection> inspection;        // the selected keyframe
  std::optional<CostLandscape> landscape;              // around the inspection's match estimate
  std::optional<Comparison> comparison;                // run B, when the user compares
  std::optional<GroundMeasure> measure;                // the user's measurement, drawn by the measure layer
  std::shared_ptr<const MapChangeReport> changes;      // the map check along the final trajectory (the changes layer)
  // A simulated log's map_change.json, read with the map check: where its map really differs.
  std::optional<std::vector<MapChangeLabel>> changeLabels;
};

// The trajectories, per-pose errors and keyframes of a session as it stands.
Analysis analysisOf(const Session& session);
// The trajectory a map check follows: the optimised one, else the odometry's.
inline const PoseTrajectory& finalTrajectory(const Analysis& a) { return a.optimized.empty() ? a.odometry : a.optimized; }
// The map check's report: kept for the changes layer, its events merged into the run's; with the
// log's labelled changes when it has them (logMapChangeLabels), and the ones the check missed as
// events at the sweep (of sweepTimestamps, along the final trajectory) nearest to each.
void setMapChanges(Analysis& analysis, std::shared_ptr<const MapChangeReport> report,
                   std::optional<std::vector<MapChangeLabel>> labels, const std::vector<int64_t>& sweepTimestamps);
void setMapChanges(Analysis& analysis, MapChangeReport report, std::optional<std::vector<MapChangeLabel>> labels,
                   const std::vector<int64_t>& sweepTimestamps);
// Run B's part of an analysis: its final trajectory with errors and its diagnostics.
Comparison comparisonOf(const Session& session, std::string name);
// Sets the trajectory file's name, its poses (city_T_ego at the sweeps) and their errors against `truth`.
void setFileTrajectory(Analysis& analysis, const PoseTrajectory& truth, PoseTrajectory file, std::string name);
// Keyframe k inspected with the session's road-point and match options, and the cost landscape
// (default extent) of its road points around the match estimate on `map` (the session's map).
// Throws Error for a keyframe out of range, without priors, or without road points.
void inspect(Analysis& analysis, const Session& session, const HdMap& map, size_t k);

}  // namespace hdprior::render
