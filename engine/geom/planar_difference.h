#pragma once
#include <cmath>
#include <numbers>

#include <Eigen/Core>

namespace hdprior {

// An angle wrapped to [-pi, pi].
inline double wrappedAngle(double a) { return std::remainder(a, 2.0 * std::numbers::pi); }

// a - b of two planar poses (x, y, yaw), the yaw difference wrapped to [-pi, pi].
inline Eigen::Vector3d planarDifference(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  Eigen::Vector3d d = a - b;
  d.z() = wrappedAngle(d.z());
  return d;
}

}  // namespace hdprior
