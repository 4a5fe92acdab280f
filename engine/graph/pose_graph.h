#pragma once
#include <cstdint>
#include <memory>
#include <numbers>
#include <vector>

#include <Eigen/Core>

#include "engine/geom/pose_trajectory.h"
#include "engine/geom/se3.h"
#include "engine/graph/pose_prior.h"

namespace hdprior {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

// Degrees per 100 m (PoseGraphOptions::odometryYawDriftSigmaDegPer100m) in radians per metre.
inline constexpr double kRadPerMetrePerDegPer100m = std::numbers::pi / 180.0 / 100.0;

struct PoseGraphOptions {
  double priorHuber = 1.0;     // robust (Huber) loss on prior residuals, in whitened units
  int maxIterations = 50;      // per solve
  int incrementalWindow = 0;   // 0: every keyframe is free in incremental solves; else only the last N
  bool fixFirst = true;        // the first keyframe is the given start (paper: the first ground-truth pose)
  // Added (as variances) to the odometry's relative covariance per keyframe: scan-to-map covariances
  // count every residual as independent and ignore the local map's own drift.
  double odometryTranslationSigma = 0.0;  // metres
  double odometryRotationSigmaDeg = 0.0;
  // The drift model (engine/graph/odometry_information.h): standard deviations per metre travelled
  // between the keyframes, added in quadrature to each translation / rotation axis. 1e-4 keeps the
  // built-in odometry's normalised keyframe errors as its relative covariance alone gives them (an
  // honest NEES) without changing the optimised ATE; small, but never zero, so a source without
  // covariances still has a model. An injected drift widens it (coveringOdometryDrift), and
  // estimateDriftModel lets the final solve take these times the factor the priors support.
  double odometryTranslationSigmaPerM = 1e-4;  // fraction of the distance
  double odometryRotationSigmaDegPerM = 1e-4;
  // The same for a trajectory given in a file (hdprior run --odometry), in place of the two above,
  // which describe the built-in odometry: a file carries no covariance of its own, and other lidar
  // odometries drift 0.5-1 % of the distance, so 1 % and 1 deg per 100 m (chosen a priori, not tuned).
  double givenOdometryTranslationSigmaPerM = 0.01;
  double givenOdometryRotationSigmaDegPerM = 0.01;
  // The odometry's scale error as a state of the graph: every keyframe's odometry step is (1 + s)
  // times too long, s starting at 0 with this standard deviation (0: no scale state, s = 0) and
  // wandering by odometryScaleSigmaPerSqrtM * sqrt(metres) from keyframe to keyframe (0: one s for
  // the whole log). A systematic scale error (0.5-1 % for real lidar odometry) makes the along-track
  // error grow with the distance; the drift model above treats each step's error as independent,
  // so where the priors observe the along-track position (a junction, a turn) the graph learns s
  // and carries the correction on to the straight roads that follow. Off by default: the along-track
  // priors of one junction share a bias, which s then carries over the whole log
  // (docs/experiments/2026-12-02-odometry-scale-state.md).
  double odometryScaleSigma = 0.0;
  double odometryScaleSigmaPerSqrtM = 0.0;
  // The odometry's systematic yaw drift as a state: every keyframe step turns b * metres too far left,
  // b one value for the whole log starting at 0 with this standard deviation (degrees per 100 m; 0: no
  // state, b = 0). Without it a scale state takes a yaw drift through a turn for a scale error. With
  // estimateDriftModel the final solve keeps the state only where the priors make it likelier
  // (DriftModelLikelihood). Off by default (docs/experiments/2026-12-04-yaw-drift-state.md).
  double odometryYawDriftSigmaDegPer100m = 0.0;
  // false: the odometry's own relative covariance (the built-in odometry's registration
  // covariances) is left out and the drift model alone weighs it, as it weighs a trajectory file
  // (then the built-in and the file path give the same graph).
  bool odometryCovariance = true;
  // The map's own error (a prior's mapSigma) as a field correlated along the route over this many
  // metres: neighbouring priors share their map error, so many of them along a street whose
  // drivable area is 0.2 m off do not add up to a 0.03 m certainty, and a good odometry is not pulled
  // onto the map's error. 50 m: the scene families' map error is smooth over 20-80 m. 0: each
  // prior's map error is its own, independent of the others'.
  double mapErrorLength = 50.0;
  // The final solve takes the per-metre sigmas above times the factor (1-100), and the map error as
  // the field above or independent, under which the run's priors were likeliest
  // (engine/pipeline/drift_model_likelihood.h); false: as configured. It needs the map error field:
  // with independent map errors only, a run of priors sharing one map error looks like drift to it
  // (docs/experiments/2026-12-02-drift-model-estimated.md).
  bool estimateDriftModel = true;
  // The final solve takes the tightest candidate whose likelihood is within this many nats of the
  // likeliest (0: the likeliest). On a drive whose odometry is good the likelihood is flat over the
  // factors, and a looser pick lets the priors pull a good odometry about. 1 nat is the least
  // evidence that is more than a bare mention (a Bayes factor of e); it costs logs whose odometry
  // drifts more than configured but shows it only weakly
  // (docs/experiments/2026-12-03-drift-model-margin.md).
  double driftModelMarginNats = 1.0;
};

struct SolveSummary {
  int iterations = 0;
  double initialCost = 0, finalCost = 0;
  bool converged = false;
};

// The pose graph of the paper's eq. (main pgo) in Ceres: keyframe poses city_T_ego,
// odometry between-factors (SE(3) residual [Log(R_meas^-1 R_i^-1 R_j); R_i^-1 (t_j - t_i) - t_meas]
// whitened by their information) and HD-map prior factors (yaw, x, y, z) with a Huber loss.
// The first keyframe is held fixed (options.fixFirst, or when no keyframe has a prior). Solves warm-start from the current
// estimates, so calling solve() after each new keyframe is the incremental use; the last call is
// the final batch solve.
class PoseGraph {
 public:
  explicit PoseGraph(PoseGraphOptions options = {});
  ~PoseGraph();
  PoseGraph(const PoseGraph&) = delete;
  PoseGraph& operator=(const PoseGraph&) = delete;

  // Returns the keyframe's index. Timestamps must increase. `initial` is the pose the correction
  // is taken against (the odometry's); the solver starts from `start` (default: initial), e.g. the
  // odometry corrected by the graph so far.
  size_t addKeyframe(int64_t timestampNs, const SE3& initial);
  size_t addKeyframe(int64_t timestampNs, const SE3& initial, const SE3& start);
  // information over the residual [rotation (3), translation (3)].
  void addOdometry(size_t i, size_t j, const SE3& iTj, const Matrix6d& information);
  void addPrior(size_t i, const PosePrior& prior);

  SolveSummary solve(bool incremental = false);

  size_t size() const { return timestamps_.size(); }
  SE3 pose(size_t i) const;
  std::vector<SE3> poses() const;
  // The odometry's scale error s at keyframe i (0 without a scale state).
  double odometryScale(size_t i) const;
  // The odometry's yaw drift b, degrees per 100 m, positive to the left (0 without the state).
  double odometryYawDrift() const;
  // Every pose of `trajectory` corrected by the keyframes' correction (optimised * initial^-1),
  // interpolated in time between keyframes and held constant beyond the first/last.
  PoseTrajectory correct(const PoseTrajectory& trajectory) const;

 private:
  bool scaleIsState() const;
  bool yawDriftIsState() const;
  double* scaleBlock(size_t i) const;
  void addScaleState();
  double* addMapOffsetState(size_t keyframe, double sigma);  // the map error at keyframe's prior

  struct Impl;
  std::unique_ptr<Impl> impl_;
  PoseGraphOptions options_;
  std::vector<int64_t> timestamps_;
  std::vector<SE3> initial_;
};

}  // namespace hdprior
