#pragma once
#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "engine/geom/se3.h"

namespace hdprior {

// Residual functors of the pose graph, templated for automatic differentiation (Ceres Jets
// find atan2/sqrt by argument-dependent lookup, so this header needs no Ceres). Parameters:
// a unit quaternion (x, y, z, w: Eigen's order) and a translation per pose.

// Odometry between-factor: r = sqrt(Omega) [2 vec(q_meas^-1 q_i^-1 q_j); R_i^-1 (t_j - t_i) - t_meas].
struct BetweenFactor {
  Eigen::Quaterniond qMeasured;
  Eigen::Vector3d tMeasured;
  Eigen::Matrix<double, 6, 6> sqrtInformation;

  BetweenFactor(const SE3& iTj, const Eigen::Matrix<double, 6, 6>& sqrtInfo)
      : qMeasured(iTj.rotation()), tMeasured(iTj.translation()), sqrtInformation(sqrtInfo) {}

  template <typename T>
  bool operator()(const T* qi, const T* ti, const T* qj, const T* tj, T* residual) const {
    const Eigen::Map<const Eigen::Quaternion<T>> Qi(qi), Qj(qj);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> Ti(ti), Tj(tj);
    const Eigen::Quaternion<T> qe = qMeasured.cast<T>().conjugate() * (Qi.conjugate() * Qj);
    Eigen::Matrix<T, 6, 1> r;
    r.template head<3>() = T(2.0) * qe.vec();
    r.template tail<3>() = Qi.conjugate() * (Tj - Ti) - tMeasured.cast<T>();
    Eigen::Map<Eigen::Matrix<T, 6, 1>> out(residual);
    out = sqrtInformation.cast<T>() * r;
    return true;
  }
};

// HD-map prior factor on (yaw, x, y, z): r = sqrt(Omega) [wrap(yaw(q) - yaw*), t - b - t*], with b
// the map's own (x, y) error where the prior is (a state of the graph; zero held constant without).
struct PriorFactor {
  double yaw;
  Eigen::Vector3d translation;
  Eigen::Matrix4d sqrtInformation;

  PriorFactor(const SE3& prior, const Eigen::Matrix4d& sqrtInfo)
      : yaw(std::atan2(prior.linear()(1, 0), prior.linear()(0, 0))), translation(prior.translation()),
        sqrtInformation(sqrtInfo) {}

  template <typename T>
  bool operator()(const T* q, const T* t, const T* mapOffset, T* residual) const {
    using std::atan2;
    using std::cos;
    using std::sin;
    // Heading of the rotated x axis: R00 = 1 - 2 (y^2 + z^2), R10 = 2 (x y + w z).
    const T r00 = T(1.0) - T(2.0) * (q[1] * q[1] + q[2] * q[2]);
    const T r10 = T(2.0) * (q[0] * q[1] + q[3] * q[2]);
    const T d = atan2(r10, r00) - T(yaw);
    Eigen::Matrix<T, 4, 1> r;
    r(0) = atan2(sin(d), cos(d));
    for (int k = 0; k < 3; ++k) r(k + 1) = t[k] - T(translation(k));
    r(1) -= mapOffset[0];
    r(2) -= mapOffset[1];
    Eigen::Map<Eigen::Matrix<T, 4, 1>> out(residual);
    out = sqrtInformation.cast<T>() * r;
    return true;
  }
};

// The map's error at one prior given the one at the previous prior, `metres` of route before it: a
// Gauss-Markov field of standard deviation sigma and correlation length L along the route,
// b_j = a b_i + w, a = exp(-metres / L), var(w) = sigma^2 (1 - a^2). The first prior's b_i is zero.
struct MapOffsetStep {
  double a, sigma;

  MapOffsetStep(double metres, double length, double fieldSigma, bool first)
      : a(first ? 0.0 : std::exp(-metres / length)), sigma(fieldSigma * std::sqrt(std::max(1.0 - a * a, 1e-6))) {}

  template <typename T>
  bool operator()(const T* bi, const T* bj, T* residual) const {
    for (int k = 0; k < 2; ++k) residual[k] = (bj[k] - T(a) * bi[k]) / T(sigma);
    return true;
  }
};

// A square root U of an information matrix (U^T U = Omega); PSD allowed.
template <int N>
Eigen::Matrix<double, N, N> sqrtInformation(const Eigen::Matrix<double, N, N>& information) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> eig(0.5 * (information + information.transpose()));
  const Eigen::Matrix<double, N, 1> s = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  return s.asDiagonal() * eig.eigenvectors().transpose();  // (S V^T)^T (S V^T) = Omega
}

}  // namespace hdprior
