#include "engine/eval/match_calibration.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>

#include "engine/geom/se2.h"

namespace hdprior {
namespace {

// The marginal variance of the unit direction u (scaled units) under a possibly singular information:
// infinite when u reaches into the information's null space or is no better known than 100 m.
double marginalVariance(const Eigen::Matrix3d& scaledInformation, const Eigen::Vector3d& u) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (scaledInformation + scaledInformation.transpose()));
  const double largest = eig.eigenvalues().maxCoeff();
  if (!(largest > 0.0)) return std::numeric_limits<double>::infinity();
  double variance = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double lambda = eig.eigenvalues()(i);
    const double c = eig.eigenvectors().col(i).dot(u);
    if (lambda <= 1e-9 * largest) {
      if (std::abs(c) > 0.1) return std::numeric_limits<double>::infinity();
      continue;
    }
    variance += c * c / lambda;
  }
  // A sigma beyond 100 m (or 10 rad x yawLength) is numerical residue of a projected-out direction.
  return variance < 1e4 ? variance : std::numeric_limits<double>::infinity();
}

DirectionCalibration calibrate(std::span<const MatchErrorSample> samples, int axis) {
  DirectionCalibration d;
  std::vector<double> nees;
  double sumSq = 0.0;
  size_t beyond = 0;
  for (const MatchErrorSample& s : samples) {
    if (!std::isfinite(s.sigma(axis))) continue;
    const double e = s.error(axis), sigma = s.sigma(axis);
    sumSq += e * e;
    const double z2 = sigma > 0.0 ? e * e / (sigma * sigma) : std::numeric_limits<double>::infinity();
    nees.push_back(z2);
    beyond += z2 > 9.0;
  }
  d.observed = nees.size();
  if (nees.empty()) return d;
  d.rms = std::sqrt(sumSq / double(nees.size()));
  d.beyond3Sigma = double(beyond) / double(nees.size());
  const size_t mid = nees.size() / 2;
  std::nth_element(nees.begin(), nees.begin() + mid, nees.end());
  d.medianNees = nees[mid];
  if (nees.size() % 2 == 0) d.medianNees = 0.5 * (d.medianNees + *std::max_element(nees.begin(), nees.begin() + mid));
  return d;
}

}  // namespace

MatchErrorSample matchErrorSample(const Eigen::Vector3d& truth, const Eigen::Vector3d& estimate,
                                  const Eigen::Matrix3d& information, double yawLength) {
  MatchErrorSample s;
  s.error = planarError(truth, estimate);
  const Eigen::Vector3d scale(1.0, 1.0, 1.0 / yawLength);  // information over (x, y, yaw * yawLength)
  const Eigen::Matrix3d scaled = scale.asDiagonal() * information * scale.asDiagonal();
  const double c = std::cos(truth.z()), sn = std::sin(truth.z());
  const Eigen::Vector3d along(c, sn, 0.0), lateral(-sn, c, 0.0), yaw(0.0, 0.0, 1.0);
  s.sigma(0) = std::sqrt(marginalVariance(scaled, along));
  s.sigma(1) = std::sqrt(marginalVariance(scaled, lateral));
  s.sigma(2) = std::sqrt(marginalVariance(scaled, yaw)) / yawLength;
  return s;
}

MatchCalibration calibrateMatches(std::span<const MatchErrorSample> samples) {
  MatchCalibration m;
  m.matches = samples.size();
  m.along = calibrate(samples, 0);
  m.lateral = calibrate(samples, 1);
  m.yaw = calibrate(samples, 2);
  return m;
}

}  // namespace hdprior
