#include "engine/graph/pose_prior.h"

#include <cmath>
#include <numbers>

#include "engine/geom/planar_difference.h"
#include "engine/geom/se2.h"
#include "engine/map/ground_height.h"
#include "engine/match/match_result.h"

namespace hdprior {

double priorAltitude(const GroundHeight& ground, double x, double y, double egoHeight) {
  return ground.bilinearAt(Eigen::Vector2d(x, y)) + egoHeight;
}

PosePrior makePosePrior(const MatchResult& match, const SE3& odometryPose, const GroundHeight& ground,
                        const PosePriorOptions& options) {
  // Where the match observes nothing (along a corridor) its estimate is arbitrary: the prior's
  // place there is the odometry's, so the altitude is looked up where the vehicle most likely is.
  const Eigen::Vector3d predicted(odometryPose.translation().x(), odometryPose.translation().y(), yawOf(odometryPose));
  const Eigen::Vector3d offset = planarDifference(match.estimate, predicted);
  const Eigen::Vector3d e = predicted + observedProjector(match.information) * offset;
  const double z = priorAltitude(ground, e.x(), e.y(), options.egoHeight);
  PosePrior prior;
  prior.pose.linear() = Eigen::AngleAxisd(e.z(), Eigen::Vector3d::UnitZ()).toRotationMatrix() * levelRotation(odometryPose);
  prior.pose.translation() = Eigen::Vector3d(e.x(), e.y(), std::isfinite(z) ? z : odometryPose.translation().z());
  // Match information is over (x, y, yaw); reorder to (yaw, x, y) and add z.
  const int order[3] = {1, 2, 0};  // match index -> prior index
  // The vehicle's heading, not the prior's yaw: where the match does not observe yaw, the prior's is
  // any point of its constraint, tens of degrees from the heading, and the along-track sigma would
  // blur the lateral place it observes.
  const Eigen::Vector3d along(std::cos(predicted.z()), std::sin(predicted.z()), 0.0);
  const Eigen::Matrix3d information = withVarianceAlong(match.informationGivenMap, along, options.alongTrackSigma);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) prior.information(order[r], order[c]) = information(r, c);
  }
  prior.information(3, 3) = std::isfinite(z) ? 1.0 / (options.altitudeSigma * options.altitudeSigma) : 0.0;
  prior.mapSigma = match.mapSigma;
  return prior;
}

namespace {
constexpr int kPlanarOrder[3] = {1, 2, 0};  // (x, y, yaw) -> (yaw, x, y, z)
}

Eigen::Matrix3d planarInformation(const PosePrior& prior) {
  Eigen::Matrix3d information;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) information(r, c) = prior.information(kPlanarOrder[r], kPlanarOrder[c]);
  }
  return information;
}

Eigen::Matrix3d marginalPlanarInformation(const PosePrior& prior) {
  const Eigen::Matrix3d exact = planarInformation(prior);
  return withVarianceAlong(withVarianceAlong(exact, Eigen::Vector3d::UnitX(), prior.mapSigma), Eigen::Vector3d::UnitY(), prior.mapSigma);
}

PosePrior withIndependentMapError(const PosePrior& prior) {
  PosePrior out = prior;
  const Eigen::Matrix3d marginal = marginalPlanarInformation(prior);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out.information(kPlanarOrder[r], kPlanarOrder[c]) = marginal(r, c);
  }
  out.mapSigma = 0.0;
  return out;
}

PriorResidual priorResidual(const PosePrior& prior, const SE3& pose) {
  PriorResidual r;
  r.error(0) = wrappedAngle(yawOf(pose) - yawOf(prior.pose));
  r.error.tail<3>() = pose.translation() - prior.pose.translation();
  r.chi2 = r.error.dot(prior.information * r.error);
  return r;
}

}  // namespace hdprior
