#pragma once
#include <vector>

#include <Eigen/Core>

#include "engine/geom/pose_trajectory.h"
#include "engine/io/argoverse_log.h"
#include "engine/odom/odometry.h"

namespace hdprior {

struct GlobalMap {
  std::vector<Eigen::Vector3f> points;  // city frame
  std::vector<float> intensity;
};

// The global map: the keyframes' deskewed sweeps placed with `trajectory` (city_T_ego at every
// sweep: the odometry's or the optimised poses), one point per voxel of `voxel` metres.
GlobalMap buildGlobalMap(const ArgoverseLog& log, const Odometry& odometry, const PoseTrajectory& trajectory, double voxel);

}  // namespace hdprior
