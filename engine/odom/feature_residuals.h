#pragma once
// The point-to-plane residual of scan-to-map registration, as a templated functor for Ceres
// automatic differentiation (it uses Eigen only, so tests can evaluate it directly).
//
// The pose is a correction delta = [v (3), w (3)] applied on the right of a fixed base pose:
// map_T_ego = base * (Exp(w), v), so the Jacobian and the covariance are in the ego (body) frame,
// translation first.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hdprior {

template <typename T>
Eigen::Matrix<T, 3, 1> rotateByVector(const T* w, const Eigen::Matrix<T, 3, 1>& p) {
  const T theta2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  const Eigen::Matrix<T, 3, 1> axisAngle(w[0], w[1], w[2]);
  if (theta2 > T(1e-16)) {
    using std::cos;
    using std::sin;
    using std::sqrt;
    const T theta = sqrt(theta2);
    const Eigen::Matrix<T, 3, 1> u = axisAngle / theta;
    return p * cos(theta) + u.cross(p) * sin(theta) + u * (u.dot(p)) * (T(1) - cos(theta));
  }
  // First order near zero, exact in value and first derivative at w = 0.
  return p + axisAngle.cross(p);
}

// The point p (ego frame) moved into the map frame by base * (Exp(w), v).
template <typename T>
Eigen::Matrix<T, 3, 1> correctedPoint(const T* delta, const Eigen::Vector3d& p, const Eigen::Isometry3d& base) {
  const Eigen::Matrix<T, 3, 1> q = rotateByVector<T>(delta + 3, p.cast<T>().eval()) + Eigen::Matrix<T, 3, 1>(delta[0], delta[1], delta[2]);
  return base.rotation().cast<T>() * q + base.translation().cast<T>();
}

// Signed distance from the moved point to the plane n.x + d = 0 (n unit).
struct PointToPlaneResidual {
  Eigen::Vector3d p, n;
  double d = 0;
  Eigen::Isometry3d base;
  template <typename T>
  bool operator()(const T* delta, T* r) const {
    r[0] = n.cast<T>().dot(correctedPoint(delta, p, base)) + T(d);
    return true;
  }
};

}  // namespace hdprior
