#include "engine/pipeline/innovation_gate.h"

#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace hdprior {
namespace {

// P(chi2 <= x) for 1-3 degrees of freedom (closed forms).
double chiSquareCdf(double x, int dof) {
  const double root = std::sqrt(0.5 * x);
  switch (dof) {
    case 1: return std::erf(root);
    case 2: return 1.0 - std::exp(-0.5 * x);
    default: return std::erf(root) - std::sqrt(2.0 * x / std::numbers::pi) * std::exp(-0.5 * x);
  }
}

}  // namespace

double chiSquareQuantile(double probability, int dof) {
  double lo = 0.0, hi = 100.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (chiSquareCdf(mid, dof) < probability ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void InnovationGate::predict(const Eigen::Vector3d& from, const SE3& previousTThis, const Matrix6d& stepInformation) {
  const double c = std::cos(from.z()), s = std::sin(from.z());
  Eigen::Matrix3d rotation;  // the step's (x, y, yaw) in its start frame -> city
  rotation << c, -s, 0, s, c, 0, 0, 0, 1;
  const Eigen::Vector2d t = rotation.topLeftCorner<2, 2>() * previousTThis.translation().head<2>();
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();  // d(next pose) / d(from)
  F(0, 2) = -t.y();
  F(1, 2) = t.x();
  const Matrix6d step = stepInformation.inverse();  // residual order [rx, ry, rz, tx, ty, tz]
  const int planar[3] = {3, 4, 2};
  Eigen::Matrix3d Q;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) Q(r, k) = step(planar[r], planar[k]);
  covariance_ = F * covariance_ * F.transpose() + rotation * Q * rotation.transpose();
}

InnovationGate::Test InnovationGate::test(const Eigen::Vector3d& predicted, const Eigen::Vector3d& prior,
                                          const Eigen::Matrix3d& priorInformation) const {
  Eigen::Vector3d innovation = prior - predicted;
  innovation.z() = std::remainder(innovation.z(), 2.0 * std::numbers::pi);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (priorInformation + priorInformation.transpose()));
  const double largest = eig.eigenvalues().maxCoeff();
  Test t;
  if (!(largest > 0.0)) return t;
  Eigen::Matrix3d basis = Eigen::Matrix3d::Zero();
  Eigen::Vector3d priorVariance = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    if (!(eig.eigenvalues()(i) > 1e-9 * largest)) continue;
    basis.col(t.dof) = eig.eigenvectors().col(i);
    priorVariance(t.dof) = 1.0 / eig.eigenvalues()(i);
    ++t.dof;
  }
  const Eigen::MatrixXd U = basis.leftCols(t.dof);
  const Eigen::MatrixXd S = U.transpose() * covariance_ * U + Eigen::MatrixXd(priorVariance.head(t.dof).asDiagonal());
  const Eigen::VectorXd y = U.transpose() * innovation;
  t.chi2 = y.dot(S.ldlt().solve(y));
  return t;
}

void InnovationGate::update(const Eigen::Matrix3d& priorInformation) {
  // (P^-1 + I)^-1 = (1 + P I)^-1 P, defined for a singular P (the fixed start) and I alike.
  const Eigen::Matrix3d posterior = (Eigen::Matrix3d::Identity() + covariance_ * priorInformation).inverse() * covariance_;
  covariance_ = 0.5 * (posterior + posterior.transpose());
}

}  // namespace hdprior
