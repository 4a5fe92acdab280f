#include "engine/pipeline/innovation_gate.h"

#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "engine/geom/angles.h"
#include "engine/geom/information.h"
#include "engine/geom/planar_difference.h"
#include "engine/geom/se2.h"

namespace hdprior {
namespace {

// How far an odometry can have drifted or slipped from the truth, one sigma: a share of the metres
// driven and of the angle turned since the start, and a yaw drift per metre. The built-in odometry
// lost up to 3 % of the metres driven in its worst turns and fell 5 deg behind in an 85 deg one.
constexpr double kDriftPerMetre = 0.01;
constexpr double kDriftPerRadianTurned = 0.02;
constexpr double kYawDriftPerMetre = 0.01 * kDegree;

// Whether a prior places the vehicle: x, y known within 2 m in some direction, and two directions
// of (yaw, x, y) fixed or more. One of yaw alone says nothing of how far the odometry has drifted,
// and one combination that agrees with the prediction (a lateral place at a junction, yaw free)
// says too little to count the reach again: a second fresh set's drive had one such prior let in
// on the true road at 200 m, then followed a polygon shifted 2.4 m with 200 m of reach.
bool placesTheVehicle(const PosePrior& prior) {
  const Eigen::Matrix2d xy = prior.information.block<2, 2>(1, 1);  // order: yaw, x, y, z
  const long observed = std::lround(observedProjector(prior.information.topLeftCorner<3, 3>()).trace());  // its rank
  return observed >= 2 && Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(xy).eigenvalues().maxCoeff() >= 0.25;
}

}  // namespace

InnovationGate::InnovationGate(const Eigen::Vector3d& start, double mapErrorLength, double probability, int reanchorPriors)
    : gate_(start, mapErrorLength), odometry_(start), probability_(probability), reanchorPriors_(reanchorPriors) {}

void InnovationGate::predict(const Eigen::Vector3d& latestPose, const SE3& previousTThis, const Matrix6d& stepInformation) {
  metres_ += previousTThis.translation().head<2>().norm();
  turned_ += std::abs(yawOf(previousTThis));
  odometry_ = offsetPose(odometry_, planarPose(previousTThis));
  gate_.setMean(latestPose);
  gate_.predict(previousTThis, stepInformation);
  if (challenger_) challenger_->predict(previousTThis, stepInformation);
}

InnovationGate::Verdict InnovationGate::judge(size_t keyframe, const PosePrior& prior, bool outsidePrediction) {
  Verdict v;
  const PlanarKalman::Innovation t = gate_.innovation(prior);
  v.chi2 = t.chi2;
  if (probability_ > 0.0 && t.dof > 0) v.quantile = chiSquareQuantile(probability_, t.dof);
  if (outsidePrediction || (v.quantile > 0.0 && t.chi2 > v.quantile)) {
    v.admitted = followGatedRun(keyframe, prior, v);
    return v;
  }
  gate_.update(t);
  challenger_.reset();
  run_.clear();
  if (placesTheVehicle(prior)) gatedSinceAdmitted_ = false;
  v.admitted = true;
  return v;
}

bool InnovationGate::followGatedRun(size_t keyframe, const PosePrior& prior, Verdict& v) {
  if (reanchorPriors_ <= 0) return false;
  bool agrees = false;
  if (challenger_) {
    const PlanarKalman::Innovation c = challenger_->innovation(prior);
    agrees = c.dof > 0 && c.chi2 <= chiSquareQuantile(probability_, c.dof);
    if (agrees) challenger_->update(c);
  }
  if (!agrees) {
    // A new run: the challenger keeps the gate's map offset, not its pose.
    challenger_ = gate_;
    challenger_->widen(kForgottenPose);
    challenger_->update(challenger_->innovation(prior));
    run_.clear();
    if (!gatedSinceAdmitted_) runStart_ = {metres_, turned_};
    gatedSinceAdmitted_ = true;
  }
  run_.push_back(keyframe);
  if (int(run_.size()) < reanchorPriors_) return false;
  if (!withinOdometryReach(challenger_->mean())) {  // the run goes on, gated
    v.beyondOdometryReach = true;
    return false;
  }
  const Eigen::Vector3d d = planarDifference(challenger_->mean(), gate_.mean());
  gate_.widen(d * d.transpose());
  gate_.update(gate_.innovation(prior));
  v.reanchored.assign(run_.begin(), run_.end() - 1);
  challenger_.reset();
  run_.clear();
  gatedSinceAdmitted_ = false;
  return true;
}

bool InnovationGate::withinOdometryReach(const Eigen::Vector3d& challengerPose) const {
  const Eigen::Vector3d d = planarDifference(challengerPose, odometry_);
  const Eigen::Matrix3d C = challenger_->covariance();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (C + C.transpose()));
  int dof = 0;  // what the run's priors observe (the rest is forgotten: kForgottenPose)
  for (int i = 0; i < 3; ++i) dof += eig.eigenvalues()(i) < 1.0;
  if (dof == 0) return true;
  const double metres = runStart_.x(), turned = runStart_.y();
  const Eigen::Vector3d reach(kDriftPerMetre * metres, kDriftPerMetre * metres,
                              kDriftPerRadianTurned * turned + kYawDriftPerMetre * metres);
  const Eigen::Matrix3d S = Eigen::Matrix3d(reach.cwiseAbs2().asDiagonal()) + C;
  return d.dot(S.ldlt().solve(d)) <= chiSquareQuantile(probability_, dof);
}

}  // namespace hdprior
