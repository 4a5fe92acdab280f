// A relative pose for the tests of odometry steps: straight ahead, optionally turning.
#pragma once
#include <Eigen/Geometry>

#include "engine/geom/se3.h"

namespace hdprior::test {

// `metres` along +x and a turn of `yaw` radians about z.
inline SE3 forward(double metres, double yaw = 0.0) {
  SE3 T = SE3::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation().x() = metres;
  return T;
}

}  // namespace hdprior::test
