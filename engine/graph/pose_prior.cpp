#include "engine/graph/pose_prior.h"

#include <cmath>

#include "engine/geom/se2.h"
#include "engine/map/ground_height.h"
#include "engine/match/match_result.h"

namespace hdprior {

double priorAltitude(const GroundHeight& ground, double x, double y, double egoHeight) {
  return ground.bilinearAt(Eigen::Vector2d(x, y)) + egoHeight;
}

PosePrior makePosePrior(const MatchResult& match, const SE3& odometryPose, const GroundHeight& ground,
                        const PosePriorOptions& options) {
  const Eigen::Vector3d& e = match.estimate;
  const double z = priorAltitude(ground, e.x(), e.y(), options.egoHeight);
  PosePrior prior;
  prior.pose.linear() = Eigen::AngleAxisd(e.z(), Eigen::Vector3d::UnitZ()).toRotationMatrix() * levelRotation(odometryPose);
  prior.pose.translation() = Eigen::Vector3d(e.x(), e.y(), std::isfinite(z) ? z : odometryPose.translation().z());
  // Match information is over (x, y, yaw); reorder to (yaw, x, y) and add z.
  const int order[3] = {1, 2, 0};  // match index -> prior index
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) prior.information(order[r], order[c]) = match.information(r, c);
  }
  prior.information(3, 3) = std::isfinite(z) ? 1.0 / (options.altitudeSigma * options.altitudeSigma) : 0.0;
  return prior;
}

}  // namespace hdprior
