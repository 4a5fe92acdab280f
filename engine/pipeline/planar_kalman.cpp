#include "engine/pipeline/planar_kalman.h"

#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "engine/geom/se2.h"

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

void PlanarKalman::predict(const SE3& previousTThis, const Matrix6d& stepInformation) {
  const double c = std::cos(mean_.z()), s = std::sin(mean_.z());
  Eigen::Matrix3d rotation;  // the step's (x, y, yaw) in its start frame -> city
  rotation << c, -s, 0, s, c, 0, 0, 0, 1;
  const Eigen::Vector2d t = rotation.topLeftCorner<2, 2>() * previousTThis.translation().head<2>();
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();  // d(next pose) / d(this pose)
  F(0, 2) = -t.y();
  F(1, 2) = t.x();
  const Matrix6d step = stepInformation.inverse();  // residual order [rx, ry, rz, tx, ty, tz]
  const int planar[3] = {3, 4, 2};
  Eigen::Matrix3d Q;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) Q(r, k) = step(planar[r], planar[k]);
  covariance_ = F * covariance_ * F.transpose() + rotation * Q * rotation.transpose();
  mean_ = offsetPose(mean_, {previousTThis.translation().x(), previousTThis.translation().y(), yawOf(previousTThis)});
}

PlanarKalman::Innovation PlanarKalman::innovation(const Eigen::Vector3d& prior, const Eigen::Matrix3d& priorInformation) const {
  Innovation n;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (priorInformation + priorInformation.transpose()));
  const double largest = eig.eigenvalues().maxCoeff();
  if (!(largest > 0.0)) return n;
  Eigen::Vector3d priorVariance = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    if (!(eig.eigenvalues()(i) > 1e-9 * largest)) continue;
    n.basis.col(n.dof) = eig.eigenvectors().col(i);
    priorVariance(n.dof) = 1.0 / eig.eigenvalues()(i);
    ++n.dof;
  }
  Eigen::Vector3d d = prior - mean_;
  d.z() = std::remainder(d.z(), 2.0 * std::numbers::pi);
  const int k = n.dof;
  const Eigen::MatrixXd U = n.basis.leftCols(k);
  const Eigen::MatrixXd S = U.transpose() * covariance_ * U + Eigen::MatrixXd(priorVariance.head(k).asDiagonal());
  const Eigen::VectorXd y = U.transpose() * d;
  const auto ldlt = S.ldlt();
  n.chi2 = y.dot(ldlt.solve(y));
  n.logDensity = -0.5 * (n.chi2 + std::log(S.determinant()) + k * std::log(2.0 * std::numbers::pi));
  n.y.head(k) = y;
  n.S.topLeftCorner(k, k) = S;
  return n;
}

void PlanarKalman::update(const Innovation& n) {
  if (n.dof == 0) return;
  const int k = n.dof;
  const Eigen::MatrixXd U = n.basis.leftCols(k);
  const Eigen::MatrixXd S = n.S.topLeftCorner(k, k);
  const Eigen::MatrixXd K = covariance_ * U * S.inverse();
  mean_ += K * n.y.head(k);
  const Eigen::Matrix3d P = (Eigen::Matrix3d::Identity() - K * U.transpose()) * covariance_;
  covariance_ = 0.5 * (P + P.transpose());
}

}  // namespace hdprior
