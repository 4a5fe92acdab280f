#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/geom/se3.h"
#include "engine/odom/odometry_options.h"

namespace hdprior {

// A keyframe of the pose graph: its pose in the odometry frame, the relative pose to the previous
// keyframe with covariance (body frame of this keyframe, [v, w]), and the sweeps since the previous
// keyframe that form its key-frame sub-map (assembled by keyframe_submap.h).
struct Keyframe {
  size_t frame = 0;  // index of the odometry frame (sweep) it sits on
  int64_t timestampNs = 0;
  SE3 odomTEgo = SE3::Identity();
  SE3 previousTThis = SE3::Identity();
  Eigen::Matrix<double, 6, 6> relativeCovariance = Eigen::Matrix<double, 6, 6>::Zero();
  std::vector<size_t> submapFrames;  // frames after the previous keyframe, up to and including this one
};

// True when the vehicle has moved at least `distance` metres or turned `rotationDeg` degrees
// since the last keyframe.
bool isNewKeyframe(const SE3& lastKeyframe, const SE3& current, const KeyframeOptions& options);

// Covariance of prev^-1 * cur from two body-frame [v, w] covariances of independent estimates.
Eigen::Matrix<double, 6, 6> relativeCovariance(const SE3& previousTThis, const Eigen::Matrix<double, 6, 6>& previous,
                                               const Eigen::Matrix<double, 6, 6>& current);

}  // namespace hdprior
