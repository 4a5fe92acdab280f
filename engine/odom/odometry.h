#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "engine/geom/pose_trajectory.h"
#include "engine/geom/se3.h"
#include "engine/io/lidar_sweep.h"
#include "engine/odom/keyframe.h"
#include "engine/odom/odometry_options.h"
#include "engine/odom/voxel_feature_map.h"

namespace hdprior {

// The estimate for one sweep.
struct OdometryFrame {
  int64_t timestampNs = 0;
  SE3 odomTEgo = SE3::Identity();        // the first sweep defines the odometry frame; with options.drift, degraded
  SE3 sweepMotion = SE3::Identity();     // ego(t)_T_ego(t + period) used to deskew this sweep
  double periodNs = 1e8;
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();  // scan-to-map, body [v, w]
  int planeResiduals = 0;                // point-to-plane residuals of the final registration round
};

// LOAM-style lidar odometry: deskew, plane features per ring, scan-to-map registration against a
// bounded local map of plane points, keyframes. Feed sweeps in time order. With options.drift the reported poses (frames,
// keyframes) carry that drift; the registration and its local map keep the undegraded estimate.
// With `given` poses (odom_T_ego at every sweep timestamp: a trajectory from another system, see
// given_odometry.h) nothing is registered: each sweep takes its given pose, with no covariance, and
// keyframes, drift and deskewing work on them as on registered ones.
class Odometry {
 public:
  explicit Odometry(const OdometryOptions& options = {}, const KeyframeOptions& keyframes = {}, PoseTrajectory given = {});

  const OdometryFrame& registerSweep(const LidarSweep& sweep);

  const std::vector<OdometryFrame>& frames() const { return frames_; }
  const std::vector<Keyframe>& keyframes() const { return keyframes_; }
  // The sweep's points in its ego frame at the sweep timestamp, deskewed as the estimate says.
  std::vector<Eigen::Vector3f> deskewed(const LidarSweep& sweep, size_t frame) const;
  size_t localMapPoints() const { return localMap_.pointCount(); }
  size_t localMapVoxels() const { return localMap_.voxelCount(); }
  bool givenPoses() const { return !given_.empty(); }

 private:
  SE3 predictedMotion(int64_t timestampNs, double& periodNs) const;
  SE3 reportedPose(const SE3& registered) const;
  OdometryFrame givenFrame(int64_t timestampNs, const SE3& pose) const;
  const OdometryFrame& addFrame(OdometryFrame frame, const SE3& registered);
  void updateKeyframes();

  OdometryOptions options_;
  KeyframeOptions keyframeOptions_;
  VoxelFeatureMap localMap_;
  std::vector<OdometryFrame> frames_;
  std::vector<SE3> registered_;  // odom_T_ego of every frame as registered (frames_ carry the drift, if any)
  std::vector<Keyframe> keyframes_;
  PoseTrajectory given_;
};

}  // namespace hdprior
