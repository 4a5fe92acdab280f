#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "engine/geom/pose_trajectory.h"
#include "engine/geom/se3.h"
#include "engine/graph/pose_prior.h"
#include "engine/option_fields.h"

namespace hdprior {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

struct PoseGraphOptions {
  double priorHuber = 1.0;  // robust (Huber) loss on prior residuals, in whitened units
  int maxIterations = 50;   // per solve
  // The drift model (engine/graph/odometry_information.h): standard deviations per metre travelled
  // between keyframes, added in quadrature to each axis of the odometry's relative covariance. Small
  // but never zero, so that a source without covariances still has a model.
  double odometryTranslationSigmaPerM = 1e-4;  // fraction of the distance
  double odometryRotationSigmaDegPerM = 1e-4;
  // The same for a trajectory given in a file (hdprior run --odometry), which carries no covariance:
  // lidar odometries drift 0.5-1 % of the distance.
  double givenOdometryTranslationSigmaPerM = 0.01;
  double givenOdometryRotationSigmaDegPerM = 0.01;
  // The map's own error (a prior's mapSigma) as a field correlated along the route over this many
  // metres, so that neighbouring priors sharing one map error do not add up to false certainty.
  // 0: each prior's map error is independent of the others'.
  double mapErrorLength = 50.0;
  // The final solve takes the tightest drift model (engine/pipeline/drift_model_likelihood.h) whose
  // likelihood is within this many nats of the likeliest (0: the likeliest): where the likelihood
  // is flat, a looser model would let the priors pull a good odometry about.
  double driftModelMarginNats = 1.0;
};
std::vector<OptionField> optionFields(PoseGraphOptions& o);  // its configuration keys


struct SolveSummary {
  int iterations = 0;
  double initialCost = 0, finalCost = 0;
  bool converged = false;
};

// The pose graph of the paper's eq. (main pgo) in Ceres: keyframe poses city_T_ego, odometry
// between-factors and HD-map prior factors (yaw, x, y, z) with a Huber loss (engine/graph/pose_factors.h).
// The first keyframe is held fixed at its given pose. Solves warm-start from the current estimates,
// so calling solve() after each new keyframe is the incremental use; the last call is the final solve.
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

  SolveSummary solve();

  size_t size() const { return timestamps_.size(); }
  SE3 pose(size_t i) const;
  std::vector<SE3> poses() const;
  // Every pose of `trajectory` corrected by the keyframes' correction (optimised * initial^-1),
  // interpolated in time between keyframes and held constant beyond the first/last.
  PoseTrajectory correct(const PoseTrajectory& trajectory) const;

 private:
  double* addMapOffsetState(size_t keyframe, double sigma);  // the map error at keyframe's prior

  struct Impl;
  std::unique_ptr<Impl> impl_;
  PoseGraphOptions options_;
  std::vector<int64_t> timestamps_;
  std::vector<SE3> initial_;
};

}  // namespace hdprior
