#include "engine/match/match_assessment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "engine/geom/angles.h"
#include "engine/geom/planar_difference.h"
#include "engine/map/boundary_distance.h"
#include "engine/map/drivable_raster.h"
#include "engine/map/ndt_grid.h"
#include "engine/map/ndt_score.h"

namespace hdprior {
namespace {


// Share of points on the drivable area, and how many distinct NDT cells they fall in.
void placement(const NdtGrid& grid, const DrivableRaster& drivable, std::span<const Eigen::Vector2d> points,
               const Eigen::Vector3d& pose, double& inlierRatio, size_t& distinctCells) {
  const Eigen::Rotation2Dd R(pose.z());
  std::vector<int64_t> cells;
  cells.reserve(points.size());
  size_t inside = 0;
  for (const Eigen::Vector2d& p : points) {
    const Eigen::Vector2d c = R * p + pose.head<2>();
    inside += drivable.contains(c);
    int col, row;
    if (grid.geometry().cellOf(c, col, row) && grid.at(col, row)) cells.push_back(int64_t(grid.geometry().index(col, row)));
  }
  std::sort(cells.begin(), cells.end());
  distinctCells = size_t(std::unique(cells.begin(), cells.end()) - cells.begin());
  inlierRatio = points.empty() ? 0.0 : double(inside) / double(points.size());
}

// Which directions the drivable area's boundary constrains, from the points near it: each
// adds J J^T with J = d(signed distance)/d(x, y, yaw) = (n, n . dR/dyaw p) for the boundary
// normal n. A straight corridor's boundary has normals across it only, so the along
// direction gets nothing; NDT's own Hessian cannot show this, since every bounded cell
// Gaussian also pulls along the road.
Eigen::Matrix3d boundaryConstraint(const BoundaryDistance& sdf, std::span<const Eigen::Vector2d> points,
                                   const Eigen::Vector3d& pose, double band) {
  const Eigen::Rotation2Dd R(pose.z());
  const double h = sdf.geometry().resolution;
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector2d& p : points) {
    const Eigen::Vector2d a = R * p, c = a + pose.head<2>();
    const double d = sdf.distance(c);
    if (!std::isfinite(d) || std::abs(d) > band) continue;
    const Eigen::Vector2d g((sdf.distance(c + Eigen::Vector2d(h, 0)) - sdf.distance(c - Eigen::Vector2d(h, 0))) / (2 * h),
                            (sdf.distance(c + Eigen::Vector2d(0, h)) - sdf.distance(c - Eigen::Vector2d(0, h))) / (2 * h));
    if (!g.allFinite() || g.norm() < 0.5) continue;  // a ridge of the distance field, no clear normal
    const Eigen::Vector2d n = g.normalized();
    const Eigen::Vector3d J(n.x(), n.y(), n.x() * -a.y() + n.y() * a.x());
    sum += J * J.transpose();
  }
  return sum;
}

// A figure in a reason, to three significant digits.
std::string figure(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

void reject(MatchResult& r, const std::string& why) {
  r.status = MatchStatus::Rejected;
  r.reason = why;
}

}  // namespace

const char* toString(MatchStatus status) {
  switch (status) {
    case MatchStatus::Accepted: return "accepted";
    case MatchStatus::Degenerate: return "degenerate";
    case MatchStatus::Rejected: return "rejected";
  }
  return "?";
}

double predictionChi2(const Eigen::Vector3d& initial, const Eigen::Vector3d& estimate, const Eigen::Vector3d& sigma) {
  const Eigen::Vector2d d = Eigen::Rotation2Dd(-initial.z()) * (estimate.head<2>() - initial.head<2>());
  const double dyaw = wrappedAngle(estimate.z() - initial.z());
  return (d.x() * d.x()) / (sigma.x() * sigma.x()) + (d.y() * d.y()) / (sigma.y() * sigma.y()) +
         dyaw * dyaw / (sigma.z() * kDegree * sigma.z() * kDegree);
}

void assessMatch(const NdtGrid& grid, const DrivableRaster& drivable, const BoundaryDistance& sdf, std::span<const Eigen::Vector2d> points,
                 const MatchOptions& o, bool timedOut, MatchResult& r) {
  const NdtScore s = scoreNdt(grid, points, r.estimate, {.outlierRatio = o.outlierRatio});
  r.score = s.score;
  r.scorePerPoint = points.empty() ? 0.0 : s.score / double(points.size());
  size_t distinctCells = 0;
  placement(grid, drivable, points, r.estimate, r.inlierRatio, distinctCells);

  // Laplace approximation: near a cell mean a term is |d1| (1 - d2/2 q^T Sigma^-1 q), so
  // -H / (|d1| d2) is the Gauss-Newton information J^T Omega J of the points as Gaussians.
  const NdtGaussConstants k = ndtGaussConstants(o.outlierRatio, grid.cellSize());
  Eigen::Matrix3d info = -s.hessian / (std::abs(k.d1) * k.d2);
  if (s.matched > 0) info *= double(distinctCells) / double(s.matched);
  const Eigen::Vector3d d(1.0, 1.0, o.yawLength);
  const auto toScaled = [&](const Eigen::Matrix3d& m) {
    const Eigen::Matrix3d t = d.cwiseInverse().asDiagonal() * m * d.cwiseInverse().asDiagonal();
    return Eigen::Matrix3d(0.5 * (t + t.transpose()));
  };
  // The observable subspace: directions the boundary constrains (scaled units).
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> geo(toScaled(boundaryConstraint(sdf, points, r.estimate, o.boundaryBand)));
  r.eigenvalues = geo.eigenvalues();
  r.eigenvectors = geo.eigenvectors();
  Eigen::Matrix3d P = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i) {
    const double lambda = r.eigenvalues(i);
    if (lambda >= o.minBoundaryPoints && lambda >= o.degenerateRatio * r.eigenvalues.maxCoeff()) {
      P += r.eigenvectors.col(i) * r.eigenvectors.col(i).transpose();
    }
  }
  // The NDT information restricted to that subspace; weak directions in it dropped too.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(P * toScaled(info) * P);
  Eigen::Matrix3d keptInfo = Eigen::Matrix3d::Zero(), keptCov = Eigen::Matrix3d::Zero();
  r.observableDirections = 0;
  for (int i = 0; i < 3; ++i) {
    const double lambda = eig.eigenvalues()(i);
    if (!(lambda >= o.minInformation)) continue;
    const Eigen::Vector3d v = eig.eigenvectors().col(i);
    keptInfo += lambda * v * v.transpose();
    keptCov += v * v.transpose() / lambda;
    ++r.observableDirections;
  }
  r.information = d.asDiagonal() * keptInfo * d.asDiagonal();
  r.covariance = d.cwiseInverse().asDiagonal() * keptCov * d.cwiseInverse().asDiagonal();
  r.informationGivenMap = r.information;
  r.mapSigma = 0.0;
  r.gateChi2 = predictionChi2(r.initial, r.estimate, o.predictionSigma);

  r.status = r.observableDirections == 3 ? MatchStatus::Accepted : MatchStatus::Degenerate;
  r.reason = r.observableDirections == 3 ? "" : std::to_string(3 - r.observableDirections) + " unobservable direction(s)";
  if (points.size() < size_t(o.minPoints)) {
    reject(r, "too few road points: " + std::to_string(points.size()) + " < " + std::to_string(o.minPoints));
  } else if (timedOut) {
    reject(r, "time over the budget of " + figure(o.timeBudgetMs) + " ms");
  } else if (r.inlierRatio < o.minInlierRatio) {
    reject(r, "inlier ratio " + figure(r.inlierRatio) + " < " + figure(o.minInlierRatio));
  } else if (r.observableDirections == 0) {
    reject(r, "no observable direction");
  } else if (r.gateChi2 > o.gateChi2) {
    reject(r, "inconsistent with the prediction: chi2 " + figure(r.gateChi2) + " > " + figure(o.gateChi2));
  }
}

}  // namespace hdprior
