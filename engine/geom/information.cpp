#include "engine/geom/information.h"

#include <algorithm>

#include <Eigen/Eigenvalues>

namespace hdprior {

Eigen::Matrix3d observedProjector(const Eigen::Matrix3d& information, double floor) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(information);
  const double largest = std::max(eig.eigenvalues().maxCoeff(), 0.0);
  Eigen::Matrix3d observed = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i) {
    if (eig.eigenvalues()(i) > std::max(1e-9 * largest, floor) && largest > 0.0) observed += eig.eigenvectors().col(i) * eig.eigenvectors().col(i).transpose();
  }
  return observed;
}

Eigen::Matrix3d withVarianceAlong(const Eigen::Matrix3d& information, const Eigen::Vector3d& a, double sigma) {
  const Eigen::Vector3d Ia = information * a;
  const double denominator = 1.0 + sigma * sigma * a.dot(Ia);
  return information - sigma * sigma * Ia * Ia.transpose() / denominator;
}

Eigen::Matrix3d marginalizedAlong(const Eigen::Matrix3d& information, const Eigen::Vector3d& a) {
  const Eigen::Vector3d Ia = information * a;
  const double aIa = a.dot(Ia);
  if (!(aIa > 0.0)) return information;
  const Eigen::Matrix3d m = information - Ia * Ia.transpose() / aIa;
  return 0.5 * (m + m.transpose());
}

}  // namespace hdprior
