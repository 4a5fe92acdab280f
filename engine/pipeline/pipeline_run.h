#pragma once
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/eval/match_calibration.h"
#include "engine/eval/trajectory_errors.h"
#include "engine/geom/pose_trajectory.h"
#include "engine/graph/pose_graph.h"
#include "engine/io/argoverse_log.h"
#include "engine/odom/given_odometry.h"
#include "engine/odom/odometry.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/prior_stage.h"
#include "engine/pipeline/prior_constraint.h"

namespace hdprior {

class HdMap;

struct PipelineOptions {
  bool priors = true;     // false: lidar odometry alone
  double mapVoxel = 0.2;  // metres, of the global map
  // The odometry's poses from another system's trajectory instead of the lidar odometry's
  // registration (hdprior run --odometry FILE); the rest of the pipeline is the same.
  std::optional<GivenOdometry> givenOdometry = std::nullopt;
};

// A sweep the run left out because it could not be read (a truncated or corrupt file, no points);
// the odometry bridged the gap (the next sweep's motion prediction spans it).
struct SkippedSweep {
  size_t index = 0;  // in the log
  std::filesystem::path file;
  std::string problem;
};

struct StageTimes {
  double odometryS = 0, roadPointsS = 0, matchS = 0, graphS = 0;  // the pipeline proper
  double pipelineS = 0;  // all of it, per sweep as it would run online, including reading sweeps
  double mapS = 0;       // rebuilding the global map afterwards
};

// A whole log through the pipeline: lidar odometry anchored at the first ground-truth pose, and with
// priors the HD-map prior stage and pose graph, whose optimised keyframes correct every sweep's pose.
struct PipelineRun {
  std::unique_ptr<Odometry> odometry;
  SE3 cityTOdom = SE3::Identity();  // the first ground-truth pose
  PoseTrajectory groundTruth;       // city_T_ego at the sweep timestamps it covers
  PoseTrajectory estimate;          // odometry, city_T_ego at every sweep
  PoseTrajectory optimized;         // with priors: every sweep corrected by the pose graph; else empty
  std::vector<KeyframeMatch> matches;  // with priors: one per keyframe
  std::vector<SE3> optimizedKeyframes;
  SolveSummary finalSolve;
  std::vector<Eigen::Vector3f> mapPoints;  // voxelised keyframe sweeps at the final poses, city frame
  std::vector<float> mapIntensity;
  StageTimes times;
  size_t maxLocalMapPoints = 0;
  OdometryDrift odometryDrift;   // injected into the odometry's reported poses (config odometry.drift)
  std::optional<GivenOdometry> givenOdometry;  // where the odometry's poses came from, when from a file
  PoseGraphOptions graphOptions;  // with priors: the graph's options in use (the drift model the priors made likeliest)
  std::vector<DriftModelLikelihood::Candidate> driftModelCandidates;  // with an estimated drift model
  std::vector<SkippedSweep> skippedSweeps;
  std::vector<size_t> frameSweeps;  // the log's sweep index of each odometry frame (they differ after a skip)

  bool hasPriors() const { return !optimized.empty(); }
  const PoseTrajectory& final() const { return hasPriors() ? optimized : estimate; }
  size_t sweepOfFrame(size_t frame) const { return frame < frameSweeps.size() ? frameSweeps[frame] : frame; }
};

// The log's HD map with the NDT grids config.match names; throws Error naming the file that is
// wrong, or the log when the map has no ground-height raster (the altitude prior needs it).
std::unique_ptr<HdMap> loadPriorMap(const ArgoverseLog& log, const Config& config);

// A Session run to the end and finished. progress(done, total) is called after each sweep. An
// unreadable or empty sweep is skipped (PipelineRun::skippedSweeps); throws Error naming the sweep
// file and the share when more than config.maxUnreadableSweepShare of them are, or naming the log
// when it has no sweeps, its poses do not cover the first sweep, or (with priors) its map lacks
// what the priors need, or the given odometry's file when it does not cover the sweeps.
PipelineRun runPipeline(const ArgoverseLog& log, const Config& config, const PipelineOptions& options = {},
                        const std::function<void(size_t, size_t)>& progress = {});

struct MatchCounts {
  size_t accepted = 0, degenerate = 0, rejected = 0;
  std::vector<PriorConstraint> constraints;  // one per keyframe: what its prior fixes, or why it has none
};

// The metrics of a run, anchored at the first pose (as the paper's table), and for the odometry,
// when there are at least 3 poses, the labelled SE(3), Sim(3) and 4-DOF alignments.
struct RunMetrics {
  TrajectoryEvaluation odometry;
  std::optional<TrajectoryEvaluation> optimized;
  std::vector<TrajectoryEvaluation> odometryAligned;
  MatchCounts matches;
  // The priors the graph used against the ground truth at their keyframes (planar pose and
  // information over x, y, yaw, as the prior factor has them), and how honest their sigmas are.
  std::vector<MatchErrorSample> priorErrors;
  MatchCalibration priorCalibration;
};
RunMetrics evaluateRun(const PipelineRun& run);

}  // namespace hdprior
