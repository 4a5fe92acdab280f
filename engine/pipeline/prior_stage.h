#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "engine/geom/pose_trajectory.h"
#include "engine/geom/se3.h"
#include "engine/graph/odometry_information.h"
#include "engine/graph/pose_graph.h"
#include "engine/graph/pose_prior.h"
#include "engine/io/lidar_sweep.h"
#include "engine/lidar/sweep_road_points.h"
#include "engine/match/match_result.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/drift_model_likelihood.h"
#include "engine/pipeline/innovation_gate.h"
#include "engine/pipeline/planar_kalman.h"

namespace hdprior {

class HdMap;
class MapMatcher;
class Odometry;
struct Keyframe;

// What the prior stage did with one keyframe.
struct KeyframeMatch {
  size_t keyframe = 0, frame = 0;  // frame: the odometry frame (Session::sweepOfFrame gives the log's sweep)
  int64_t timestampNs = 0;
  SE3 predicted = SE3::Identity();  // the odometry pose corrected by the graph so far: the match's start
  MatchResult match;
  bool hasPrior = false;            // accepted or degenerate: a prior went into the graph
  PosePrior prior;
  double innovationChi2 = 0.0;      // the prior against the graph's prediction (PlanarKalman); 0 without a prior
  bool gated = false;               // the innovation gate left the prior out (`match` is as the matcher gave it)
  // The match moved farther from the prediction than the matcher's fixed gate (match.gate_chi2) allows:
  // the prior goes in only with a run of gated priors that agree with it.
  bool outsidePrediction = false;
  double gateQuantile = 0.0;        // the gate's chi-square quantile for the prior (0: no gate)
  // Gated, and its run of agreeing priors is farther from the odometry than the odometry could have
  // drifted by the run's start: the map there, not the odometry, is taken for what is wrong.
  bool beyondOdometryReach = false;
};

// Loads the sweep of an odometry frame.
using SweepOf = std::function<std::shared_ptr<const LidarSweep>(size_t frame)>;

// The sweep keyframe k's road points come from, and the rotation that levels it (the keyframe's roll
// and pitch in the city).
struct KeyframeSweep {
  std::shared_ptr<const LidarSweep> sweep;
  Eigen::Matrix3d egoLevel = Eigen::Matrix3d::Identity();
};
KeyframeSweep keyframeSweep(const Odometry& odometry, size_t keyframe, const SE3& cityTOdom, const SweepOf& sweepOf);

struct PriorStageTimes {
  double roadPointsS = 0, matchS = 0, graphS = 0;
};

// The paper's HD-map prior stage, fed keyframe by keyframe as the odometry makes them: the keyframe's
// road points (from its sweep), scan-to-map matching from the odometry pose
// corrected by the graph so far, the pose prior (yaw, x, y from the match, z from the ground
// height) for accepted and degenerate matches, the odometry between-factor (its covariance plus the
// graph's drift model: engine/graph/odometry_information.h),
// and an incremental, warm-started solve. finish() is the final batch solve.
class PriorStage {
 public:
  // cityTOdom places the odometry frame in the city (the first ground-truth pose). givenPoses: the
  // odometry's poses come from a file, and the graph takes its drift model (odometryDriftModel).
  PriorStage(const HdMap& map, const Config& config, const SE3& cityTOdom, bool givenPoses = false);
  ~PriorStage();
  PriorStage(const PriorStage&) = delete;
  PriorStage& operator=(const PriorStage&) = delete;

  // The odometry's newest keyframe; sweepOf loads the sweep of an odometry frame.
  void addKeyframe(const Odometry& odometry, const SweepOf& sweepOf);
  // The final batch solve, under the drift model the priors made likeliest (DriftModelLikelihood).
  SolveSummary finish(const Odometry& odometry);
  // Rebuilds the graph from the keyframes and matches so far with other prior and graph options
  // (priors re-made from the same matches), warm-started from the current poses; does not solve.
  void rebuildGraph(const Odometry& odometry, const PosePriorOptions& prior, const PoseGraphOptions& graph);

  const std::vector<KeyframeMatch>& matches() const { return matches_; }
  const PoseGraph& graph() const { return *graph_; }
  const PriorStageTimes& times() const { return times_; }
  // The graph options in use: the configuration's with the source's drift model, after finish() the likeliest.
  const PoseGraphOptions& graphOptions() const { return config_.graph; }
  // The drift models the priors were weighed under (empty before the first keyframe).
  std::vector<DriftModelLikelihood::Candidate> driftModelCandidates() const {
    return driftModels_ ? driftModels_->scored() : std::vector<DriftModelLikelihood::Candidate>{};
  }

 private:
  SE3 predictedPose(const Keyframe& keyframe) const;
  // The innovation gate on m's prior; true when it let in earlier gated priors with it.
  bool gatePrior(KeyframeMatch& m);
  void rebuild(const Odometry& odometry);

  const HdMap& map_;
  Config config_;
  SE3 cityTOdom_;
  bool givenPoses_;
  std::unique_ptr<MapMatcher> matcher_;
  std::unique_ptr<PoseGraph> graph_;
  InnovationGate gate_;
  std::optional<DriftModelLikelihood> driftModels_;
  std::vector<KeyframeMatch> matches_;
  PriorStageTimes times_;
};

}  // namespace hdprior
