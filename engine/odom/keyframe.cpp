#include "engine/odom/keyframe.h"

#include <cmath>

namespace hdprior {

bool isNewKeyframe(const SE3& lastKeyframe, const SE3& current, const KeyframeOptions& o) {
  const SE3 rel = lastKeyframe.inverse() * current;
  const double angleDeg = Eigen::AngleAxisd(rel.rotation()).angle() * 180.0 / M_PI;
  return rel.translation().norm() >= o.distance || angleDeg >= o.rotationDeg;
}

Eigen::Matrix<double, 6, 6> relativeCovariance(const SE3& previousTThis, const Eigen::Matrix<double, 6, 6>& previous,
                                               const Eigen::Matrix<double, 6, 6>& current) {
  // A body perturbation of the previous pose reaches this frame through the adjoint of this_T_previous.
  const SE3 T = previousTThis.inverse();
  const Eigen::Matrix3d R = T.rotation();
  const Eigen::Vector3d t = T.translation();
  Eigen::Matrix3d tx;
  tx << 0, -t.z(), t.y(), t.z(), 0, -t.x(), -t.y(), t.x(), 0;
  Eigen::Matrix<double, 6, 6> Ad = Eigen::Matrix<double, 6, 6>::Zero();
  Ad.topLeftCorner<3, 3>() = R;
  Ad.topRightCorner<3, 3>() = tx * R;
  Ad.bottomRightCorner<3, 3>() = R;
  return current + Ad * previous * Ad.transpose();
}

}  // namespace hdprior
