#pragma once
#include <vector>

#include <Eigen/Core>

#include "engine/geom/pose_trajectory.h"
#include "engine/odom/odometry.h"
#include "engine/pipeline/prior_stage.h"

namespace hdprior {

struct GlobalMap {
  std::vector<Eigen::Vector3f> points;  // city frame
  std::vector<float> intensity;
};

// The global map: the keyframes' deskewed sweeps (sweepOf: an odometry frame's) placed with
// `trajectory` (city_T_ego at every odometry frame: the odometry's or the optimised poses), one
// point per voxel of `voxel` metres.
GlobalMap buildGlobalMap(const SweepOf& sweepOf, const Odometry& odometry, const PoseTrajectory& trajectory, double voxel);

}  // namespace hdprior
