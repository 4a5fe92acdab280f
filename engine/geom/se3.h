#pragma once
#include <Eigen/Geometry>

namespace hdprior {

// Rigid transform a_T_b: maps b-frame points into frame a.
using SE3 = Eigen::Isometry3d;

inline SE3 makeSE3(const Eigen::Quaterniond& q, const Eigen::Vector3d& t) {
  SE3 T = SE3::Identity();
  T.linear() = q.normalized().toRotationMatrix();
  T.translation() = t;
  return T;
}

// Slerp on rotation, linear on translation; s in [0, 1].
inline SE3 interpolate(const SE3& a, const SE3& b, double s) {
  const Eigen::Quaterniond qa(a.rotation()), qb(b.rotation());
  return makeSE3(qa.slerp(s, qb), (1.0 - s) * a.translation() + s * b.translation());
}

}  // namespace hdprior
