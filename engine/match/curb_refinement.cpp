#include "engine/match/curb_refinement.h"

#include <cmath>
#include <vector>

#include <Eigen/Cholesky>

#include "engine/map/boundary_distance.h"

namespace hdprior {
namespace {

// The boundary distance and its gradient (central differences over one raster cell).
bool distanceAndGradient(const BoundaryDistance& b, const Eigen::Vector2d& q, double& d, Eigen::Vector2d& g) {
  const double h = b.geometry().resolution;
  d = b.distance(q);
  const double dx = b.distance(q + Eigen::Vector2d(h, 0)) - b.distance(q - Eigen::Vector2d(h, 0));
  const double dy = b.distance(q + Eigen::Vector2d(0, h)) - b.distance(q - Eigen::Vector2d(0, h));
  g = Eigen::Vector2d(dx, dy) / (2.0 * h);
  return std::isfinite(d) && g.allFinite();
}

}  // namespace

CurbRefinement refineOnCurbs(const BoundaryDistance& boundary, std::span<const Eigen::Vector2d> curbPoints,
                             const Eigen::Vector3d& start, const CurbRefinementOptions& o) {
  CurbRefinement r;
  r.pose = start;
  // The points near the boundary at the start; the others are not curbs of this map (stale map, kerb
  // of a traffic island not in it, a step on the road).
  std::vector<Eigen::Vector2d> used;
  {
    const double c = std::cos(start.z()), s = std::sin(start.z());
    for (const Eigen::Vector2d& p : curbPoints) {
      const Eigen::Vector2d q(c * p.x() - s * p.y() + start.x(), s * p.x() + c * p.y() + start.y());
      const double d = boundary.distance(q);
      if (std::isfinite(d) && std::abs(d) <= o.maxDistance) used.push_back(p);
    }
  }
  r.used = used.size();
  if (used.size() < size_t(o.minPoints)) return r;
  for (; r.iterations < o.iterations; ++r.iterations) {
    const double c = std::cos(r.pose.z()), s = std::sin(r.pose.z());
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (const Eigen::Vector2d& p : used) {
      const Eigen::Vector2d rotated(c * p.x() - s * p.y(), s * p.x() + c * p.y());
      double d;
      Eigen::Vector2d g;
      if (!distanceAndGradient(boundary, rotated + r.pose.head<2>(), d, g)) continue;
      const Eigen::Vector3d J(g.x(), g.y(), g.x() * -rotated.y() + g.y() * rotated.x());
      const double w = std::abs(d) <= o.huber ? 1.0 : o.huber / std::abs(d);
      H += w * J * J.transpose();
      b += w * J * d;
    }
    // Levenberg damping keeps the unobserved directions where they are.
    H.diagonal().array() += 1e-3 * H.trace() / 3.0 + 1e-9;
    // Parameters (lateral, yaw): the pose moves only across its heading.
    Eigen::Matrix<double, 3, 2> B = Eigen::Matrix<double, 3, 2>::Zero();
    B(0, 0) = -std::sin(r.pose.z());
    B(1, 0) = std::cos(r.pose.z());
    B(2, 1) = 1.0;
    const Eigen::Vector3d step = -B * (B.transpose() * H * B).ldlt().solve(B.transpose() * b);
    if (!step.allFinite()) break;
    r.pose += step;
    if (step.head<2>().norm() < 1e-4 && std::abs(step.z()) < 1e-5) break;
  }
  return r;
}

}  // namespace hdprior
