#pragma once
#include <vector>

#include <Eigen/Core>

#include "engine/geom/se3.h"
#include "engine/odom/odometry_options.h"
#include "engine/odom/voxel_feature_map.h"

namespace hdprior {

struct RegistrationResult {
  SE3 mapTEgo = SE3::Identity();
  // Covariance of the body-frame correction [v, w] at the optimum: s^2 (J^T J)^-1 with s^2 the
  // residual variance (robust-weighted Jacobian).
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Identity();
  int planeResiduals = 0;
  double rmsResidual = 0;
};

// One correspondence search: the plane n.x + offset = 0 fitted to the 5 nearest map points of a
// query point in the map frame; false when the neighbourhood is not plane-like.
bool fitPlane(const Eigen::Vector3f* neighbours, int count, Eigen::Vector3d& normal, double& offset);

// Scan-to-map registration of plane query points (ego frame) against the local map with
// point-to-plane residuals under a Huber loss, solved with Ceres from `guess`.
RegistrationResult registerFeatures(const std::vector<Eigen::Vector3f>& planes, const VoxelFeatureMap& planeMap,
                                    const SE3& guess, const RegistrationOptions& options);

}  // namespace hdprior
