#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "engine/geom/se3.h"
#include "engine/graph/odometry_information.h"
#include "engine/graph/pose_prior.h"
#include "engine/pipeline/planar_kalman.h"

namespace hdprior {

// Lets a prior into the graph only if it agrees with the graph's prediction: its innovation under
// the prediction's covariance (a PlanarKalman over the latest keyframe) plus its own is below the
// `probability` chi-square quantile.
//
// A gate trusts its prediction, and an odometry failure its covariance did not show (a turn where
// the lidar odometry slipped metres) would shut out every right prior after it. So the gated priors
// are followed too: a challenger prediction starts at the first gated prior, without the graph's
// pose (100 m, 90 deg), and is carried by the odometry; while the next gated priors pass its gate
// they form one run. `reanchorPriors` of them in a run agree with one another and not with the
// prediction: the prediction is what went wrong, the gate widens by the disagreement and the whole
// run goes in. Unless the odometry could not have drifted that far from the run's pose by the run's
// first prior (withinOdometryReach): then the map is what went wrong there (a polygon shifted under
// the car), and the run stays out however long it grows.
class InnovationGate {
 public:
  InnovationGate() = default;
  InnovationGate(const Eigen::Vector3d& start, double mapErrorLength, double probability, int reanchorPriors);

  // To the next keyframe: the graph's pose at the latest one, then the odometry step.
  void predict(const Eigen::Vector3d& latestPose, const SE3& previousTThis, const Matrix6d& stepInformation);

  struct Verdict {
    bool admitted = false;
    double chi2 = 0.0;                // against the graph's prediction
    double quantile = 0.0;            // the chi-square quantile chi2 is held against (0: no gate)
    std::vector<size_t> reanchored;   // admitted: the earlier gated priors of the run that go in with it
    bool beyondOdometryReach = false;  // gated: its run is farther from the odometry than it could have drifted
  };
  // `outsidePrediction`: the prior is held out as if its chi-square were above the quantile.
  Verdict judge(size_t keyframe, const PosePrior& prior, bool outsidePrediction = false);

 private:
  bool followGatedRun(size_t keyframe, const PosePrior& prior, Verdict& verdict);

  // Whether the odometry could have drifted or slipped from the truth as far as the run's pose is
  // from it, by the run's first prior.
  bool withinOdometryReach(const Eigen::Vector3d& challengerPose) const;

  PlanarKalman gate_;
  std::optional<PlanarKalman> challenger_;
  // Where the odometry alone puts the pose, and the metres and radians it has driven and turned
  // since the start; at the first gated prior since the gate last let in one that places the vehicle. A run re-anchors only
  // where the odometry could have drifted or slipped that far by then: a shifted polygon's priors
  // disagree from where they begin, an odometry failure grows with the drive. Runs that break off
  // and start again while nothing is let in keep that first reach, or a long drive on a shifted
  // polygon would in the end be followed.
  Eigen::Vector3d odometry_ = Eigen::Vector3d::Zero();
  double metres_ = 0.0, turned_ = 0.0;
  Eigen::Vector2d runStart_ = Eigen::Vector2d::Zero();
  bool gatedSinceAdmitted_ = false;
  std::vector<size_t> run_;  // keyframes of the gated priors that agree with the challenger
  double probability_ = 0.99;
  int reanchorPriors_ = 3;
};

}  // namespace hdprior
