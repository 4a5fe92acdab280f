#pragma once
#include <cmath>

#include <Eigen/Core>

#include "engine/geom/se3.h"

namespace hdprior {

// SE(2) poses on the map plane are Eigen::Vector3d (x, y, yaw).

// The yaw of a 3-D pose: the heading of its x axis projected on the plane.
inline double yawOf(const SE3& T) { return std::atan2(T.linear()(1, 0), T.linear()(0, 0)); }

inline Eigen::Vector3d planarPose(const SE3& T) { return {T.translation().x(), T.translation().y(), yawOf(T)}; }

// The roll and pitch part R_rp of T's rotation (R = Rz(yaw) R_rp): rotates ego-frame points
// into the level frame that shares the ego's heading.
inline Eigen::Matrix3d levelRotation(const SE3& T) {
  return Eigen::AngleAxisd(-yawOf(T), Eigen::Vector3d::UnitZ()).toRotationMatrix() * T.linear();
}

// The pose moved by an offset (dx forward, dy left, dyaw) in its own frame.
inline Eigen::Vector3d offsetPose(const Eigen::Vector3d& pose, const Eigen::Vector3d& offset) {
  const double c = std::cos(pose.z()), s = std::sin(pose.z());
  return {pose.x() + c * offset.x() - s * offset.y(), pose.y() + s * offset.x() + c * offset.y(), pose.z() + offset.z()};
}

// The error of `estimate` against `truth` in truth's frame: (along, lateral, yaw), yaw wrapped.
inline Eigen::Vector3d planarError(const Eigen::Vector3d& truth, const Eigen::Vector3d& estimate) {
  const double c = std::cos(truth.z()), s = std::sin(truth.z());
  const Eigen::Vector2d d = estimate.head<2>() - truth.head<2>();
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y(), std::remainder(estimate.z() - truth.z(), 2.0 * M_PI)};
}

}  // namespace hdprior
