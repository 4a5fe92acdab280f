#include "engine/pipeline/planar_kalman.h"

#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "engine/geom/planar_difference.h"
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

PlanarKalman::PlanarKalman(const Eigen::Vector3d& start, double mapErrorLength) : mapErrorLength_(mapErrorLength) {
  state_.head<3>() = start;
}

void PlanarKalman::predict(const SE3& previousTThis, const Matrix6d& stepInformation) {
  const Eigen::Vector3d pose = mean();
  const double c = std::cos(pose.z()), s = std::sin(pose.z());
  Eigen::Matrix3d rotation;  // the step's (x, y, yaw) in its start frame -> city
  rotation << c, -s, 0, s, c, 0, 0, 0, 1;
  const Eigen::Vector2d t = rotation.topLeftCorner<2, 2>() * previousTThis.translation().head<2>();
  const double metres = previousTThis.translation().head<2>().norm();
  Matrix5d F = Matrix5d::Identity();  // d(next state) / d(this state): the map offset stays
  F(0, 2) = -t.y();
  F(1, 2) = t.x();
  const Matrix6d step = stepInformation.inverse();  // residual order [rx, ry, rz, tx, ty, tz]
  const int planar[3] = {3, 4, 2};
  Eigen::Matrix3d Q;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) Q(r, k) = step(planar[r], planar[k]);
  covariance_ = F * covariance_ * F.transpose();
  covariance_.topLeftCorner<3, 3>() += rotation * Q * rotation.transpose();
  state_.head<3>() = offsetPose(pose, {previousTThis.translation().x(), previousTThis.translation().y(), yawOf(previousTThis)});
  metresSinceOffset_ += metres;
}

PlanarKalman::State PlanarKalman::atPrior(double mapSigma) const {
  State s{state_, covariance_};
  if (!(mapErrorLength_ > 0.0 && mapSigma > 0.0)) return s;
  // As the graph's MapOffsetStep: the first offset is N(0, sigma^2), each next a * previous + noise.
  const double a = hasMapOffset_ ? std::exp(-metresSinceOffset_ / mapErrorLength_) : 0.0;
  s.mean.segment<2>(3) *= a;
  s.covariance.middleRows<2>(3) *= a;
  s.covariance.middleCols<2>(3) *= a;
  s.covariance.block<2, 2>(3, 3).diagonal().array() += mapSigma * mapSigma * (1.0 - a * a);
  return s;
}

namespace {

// What a prior observes of the state: the pose, plus the map offset in x, y when it carries one.
Eigen::Matrix<double, 3, 5> observation(bool withOffset) {
  Eigen::Matrix<double, 3, 5> J = Eigen::Matrix<double, 3, 5>::Zero();
  J.leftCols<3>().setIdentity();
  if (withOffset) J.block<2, 2>(0, 3).setIdentity();
  return J;
}

}  // namespace

PlanarKalman::Innovation PlanarKalman::innovation(const Eigen::Vector3d& prior, const Eigen::Matrix3d& priorInformation,
                                                  double mapSigma) const {
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
  n.mapSigma = mapErrorLength_ > 0.0 && mapSigma > 0.0 ? mapSigma : 0.0;
  const State s = atPrior(n.mapSigma);
  const Eigen::Matrix<double, 3, 5> J = observation(n.mapSigma > 0.0);
  const Eigen::Vector3d d = planarDifference(prior, J * s.mean);
  const int k = n.dof;
  const Eigen::MatrixXd H = n.basis.leftCols(k).transpose() * J;
  const Eigen::MatrixXd S = H * s.covariance * H.transpose() + Eigen::MatrixXd(priorVariance.head(k).asDiagonal());
  const Eigen::VectorXd y = n.basis.leftCols(k).transpose() * d;
  const auto ldlt = S.ldlt();
  n.chi2 = y.dot(ldlt.solve(y));
  n.logDensity = -0.5 * (n.chi2 + std::log(S.determinant()) + k * std::log(2.0 * std::numbers::pi));
  n.y.head(k) = y;
  n.S.topLeftCorner(k, k) = S;
  return n;
}

PlanarKalman::Innovation PlanarKalman::innovation(const PosePrior& prior) const {
  const bool field = mapErrorLength_ > 0.0 && prior.mapSigma > 0.0;
  return field ? innovation(planarPose(prior.pose), planarInformation(prior), prior.mapSigma)
               : innovation(planarPose(prior.pose), marginalPlanarInformation(prior));
}

void PlanarKalman::update(const Innovation& n) {
  if (n.dof == 0) return;
  const int k = n.dof;
  const State s = atPrior(n.mapSigma);
  const Eigen::MatrixXd H = n.basis.leftCols(k).transpose() * observation(n.mapSigma > 0.0);
  const Eigen::MatrixXd S = n.S.topLeftCorner(k, k);
  const Eigen::MatrixXd K = s.covariance * H.transpose() * S.inverse();
  state_ = s.mean + K * n.y.head(k);
  const Matrix5d P = (Matrix5d::Identity() - K * H) * s.covariance;
  covariance_ = 0.5 * (P + P.transpose());
  if (n.mapSigma > 0.0) {
    hasMapOffset_ = true;
    metresSinceOffset_ = 0.0;
  }
}

}  // namespace hdprior
