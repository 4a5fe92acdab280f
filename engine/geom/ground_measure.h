#pragma once
#include <Eigen/Core>

namespace hdprior {

// A measurement between two points on the ground (city frame): the planar distance and its
// components along and across a heading (the ego's at the current frame; lateral positive to the
// left), and the rise from the first point to the second.
struct GroundMeasure {
  Eigen::Vector3d from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::Zero();
  double heading = 0.0;  // radians, city frame
  double distance = 0.0, along = 0.0, lateral = 0.0, rise = 0.0;
};

GroundMeasure measureGround(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double headingYaw);

}  // namespace hdprior
