#pragma once
#include <vector>

#include <Eigen/Core>

#include "engine/geom/se3.h"
#include "engine/io/lidar_sweep.h"

namespace hdprior {

// The pose at fraction s of a motion (s may exceed 1): rotation angle and translation scaled by s.
SE3 scaleMotion(const SE3& motion, double s);

// Moves each point from the ego frame at its own time (sweep timestamp + offset_ns) to the ego
// frame at the sweep timestamp, with constant velocity: `motion` is ego(t)_T_ego(t + periodNs).
Eigen::Vector3f deskewPoint(const LidarPoint& p, const SE3& motion, double periodNs);
std::vector<Eigen::Vector3f> deskewSweep(const std::vector<LidarPoint>& points, const SE3& motion, double periodNs);

// The stored positions unchanged (points already compensated to the sweep timestamp).
std::vector<Eigen::Vector3f> sweepPositions(const std::vector<LidarPoint>& points);

}  // namespace hdprior
