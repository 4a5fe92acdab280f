#include "engine/match/match_uncertainty.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "engine/geom/angles.h"
#include "engine/geom/se2.h"
#include "engine/map/boundary_distance.h"

namespace hdprior {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Counts the road points off the drivable area (beyond `margin` outside it) and the curb points off
// the boundary (beyond `curbBand` from it) at a pose.
struct OffCounter {
  const BoundaryDistance& sdf;
  std::span<const Eigen::Vector2d> road;
  std::vector<Eigen::Vector2d> curbs;  // those on the boundary at the estimate
  int stride;
  double margin, curbBand;

  struct Counts {
    int road = 0, curbs = 0;
  };
  // Counting stops once a count passes its limit: the pose is implausible either way.
  Counts operator()(const Eigen::Vector3d& pose, const Counts& limit) const {
    const Eigen::Rotation2Dd R(pose.z());
    Counts n;
    for (const Eigen::Vector2d& c : curbs)
      if (!(std::abs(sdf.cellDistance(R * c + pose.head<2>())) <= curbBand) && ++n.curbs > limit.curbs) return n;
    for (size_t i = 0; i < road.size(); i += size_t(stride))
      if (!(sdf.cellDistance(R * road[i] + pose.head<2>()) <= margin) && ++n.road > limit.road) return n;
    return n;
  }
  int sampled() const { return int((road.size() + size_t(stride) - 1) / size_t(stride)); }
};

struct Allowed {
  int road = 0, curbs = 0;
  bool exceeded(const OffCounter::Counts& c, const OffCounter::Counts& best) const {
    return c.road > best.road + road || c.curbs > best.curbs + curbs;
  }
};

OffCounter::Counts lowest(const OffCounter::Counts& a, const OffCounter::Counts& b) {
  return {std::min(a.road, b.road), std::min(a.curbs, b.curbs)};
}

// The offset (>= 0) along `unit` (estimate frame) at which the off counts first rise more than
// allowed above the lowest met on the way: doubling from `first`, then three bisections.
double plausibleReach(const OffCounter& off, const Eigen::Vector3d& estimate, const Eigen::Vector3d& unit, double first,
                      double limit, const Allowed& allowed) {
  OffCounter::Counts best{std::numeric_limits<int>::max() / 2, std::numeric_limits<int>::max() / 2};
  const auto at = [&](double s) {
    return off(offsetPose(estimate, unit * s), {best.road + allowed.road, best.curbs + allowed.curbs});
  };
  best = at(0.0);
  double inside = 0.0, outside = kInfinity;
  for (double s = first; s <= limit; s *= 2.0) {
    const OffCounter::Counts c = at(s);
    if (allowed.exceeded(c, best)) {
      outside = s;
      break;
    }
    best = lowest(best, c);
    inside = s;
  }
  if (!std::isfinite(outside)) return kInfinity;
  for (int i = 0; i < 3; ++i) {
    const double mid = 0.5 * (inside + outside);
    const OffCounter::Counts c = at(mid);
    if (allowed.exceeded(c, best)) {
      outside = mid;
    } else {
      inside = mid;
      best = lowest(best, c);
    }
  }
  return 0.5 * (inside + outside);
}

// R maps city (x, y, yaw) offsets into the estimate's frame (along, lateral, yaw).
Eigen::Matrix3d toEstimateFrame(double yaw) {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  R.topLeftCorner<2, 2>() = Eigen::Rotation2Dd(-yaw).toRotationMatrix();
  return R;
}

// Marginal variances of an information's axes (scaled units); +infinity where an axis reaches into
// its null space.
Eigen::Vector3d axisVariances(const Eigen::Matrix3d& information) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (information + information.transpose()));
  const double largest = eig.eigenvalues().maxCoeff();
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int axis = 0; axis < 3; ++axis) {
    if (!(largest > 0.0)) {
      v(axis) = kInfinity;
      continue;
    }
    for (int i = 0; i < 3; ++i) {
      const double lambda = eig.eigenvalues()(i), c = eig.eigenvectors()(axis, i);
      if (lambda <= 1e-9 * largest) {
        if (std::abs(c) > 0.1) v(axis) = kInfinity;
      } else if (std::isfinite(v(axis))) {
        v(axis) += c * c / lambda;
      }
    }
  }
  return v;
}

}  // namespace

Eigen::Vector3d plausibleHalfWidths(const BoundaryDistance& sdf, std::span<const Eigen::Vector2d> road,
                                    std::span<const Eigen::Vector2d> curbs, const Eigen::Vector3d& estimate,
                                    const MatchOptions& o) {
  OffCounter off{sdf, road, {}, std::max(1, o.evidenceStride), o.evidenceMargin, o.evidenceCurbBand};
  const Eigen::Rotation2Dd R(estimate.z());
  for (const Eigen::Vector2d& c : curbs)
    if (std::abs(sdf.cellDistance(R * c + estimate.head<2>())) <= o.evidenceCurbBand) off.curbs.push_back(c);
  if (int(off.curbs.size()) < o.minCurbPoints) off.curbs.clear();
  const Allowed allowed{std::max(o.evidenceMinPoints, int(std::ceil(o.evidenceShare * off.sampled()))),
                        std::max(o.evidenceMinPoints, int(std::ceil(o.evidenceCurbShare * double(off.curbs.size()))))};
  Eigen::Vector3d widths;
  for (int axis = 0; axis < 3; ++axis) {
    const bool yaw = axis == 2;
    const double first = yaw ? 0.1 * kDegree : 0.05, limit = yaw ? o.evidenceMaxYawDeg * kDegree : o.evidenceMaxOffset;
    const Eigen::Vector3d unit = Eigen::Vector3d::Unit(axis);
    const double plus = plausibleReach(off, estimate, unit, first, limit, allowed);
    const double minus = plausibleReach(off, estimate, -unit, first, limit, allowed);
    widths(axis) = 0.5 * (plus + minus);
  }
  return widths;
}

void widenToEvidence(const Eigen::Vector3d& halfWidths, const MatchOptions& o, MatchResult& r) {
  // Work in the estimate's frame, scaled: (along, lateral, yaw * yawLength).
  const Eigen::Vector3d scale(1.0, 1.0, o.yawLength);
  const Eigen::Matrix3d fromCity = scale.asDiagonal() * toEstimateFrame(r.estimate.z());  // city offset -> scaled local
  const Eigen::Matrix3d toCity = fromCity.inverse();
  const Eigen::Matrix3d laplaceInformation = toCity.transpose() * r.information * toCity;
  const Eigen::Vector3d evidenceSigma = halfWidths.cwiseProduct(scale) / o.evidenceKappa;
  const Eigen::Vector3d mapSigma(o.mapSigma, o.mapSigma, o.mapSigmaYawDeg * kDegree * o.yawLength);
  const Eigen::Vector3d cap(o.maxSigmaAlong, o.maxSigmaLateral, o.maxSigmaYawDeg * kDegree * o.yawLength);

  // Each direction the Laplace information observes (its eigenvectors u): its variance raised to the
  // evidence's along u (the axes' evidence projected on u), plus the map's error; a direction that then
  // exceeds its cap, or that leans on an axis the evidence leaves unbounded, is dropped.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (laplaceInformation + laplaceInformation.transpose()));
  const double largest = eig.eigenvalues().maxCoeff();
  const Eigen::Vector3d mapSigmaYaw(0.0, 0.0, mapSigma.z());
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero(), covariance = Eigen::Matrix3d::Zero(), givenMap = Eigen::Matrix3d::Zero();
  r.observableDirections = 0;
  for (int i = 0; i < 3; ++i) {
    const double lambda = eig.eigenvalues()(i);
    if (!(largest > 0.0) || lambda <= 1e-9 * largest) continue;
    const Eigen::Vector3d u = eig.eigenvectors().col(i);
    const Eigen::Vector3d weight = u.cwiseAbs2();
    bool unbounded = false;
    for (int a = 0; a < 3; ++a) unbounded |= weight(a) > 0.01 && !std::isfinite(evidenceSigma(a));
    if (unbounded) continue;
    double evidence = 0.0;
    for (int a = 0; a < 3; ++a)
      if (std::isfinite(evidenceSigma(a))) evidence += weight(a) * evidenceSigma(a) * evidenceSigma(a);
    const double matchVariance = std::max(1.0 / lambda, evidence) + weight.dot(mapSigmaYaw.cwiseAbs2());
    const double variance = matchVariance + weight.dot(mapSigma.cwiseAbs2() - mapSigmaYaw.cwiseAbs2());
    if (variance > weight.dot(cap.cwiseAbs2())) continue;
    information += u * u.transpose() / variance;
    givenMap += u * u.transpose() / matchVariance;
    covariance += u * u.transpose() * variance;
    ++r.observableDirections;
  }
  r.evidenceHalfWidths = halfWidths;
  r.laplaceSigmas = axisVariances(laplaceInformation).cwiseSqrt().cwiseQuotient(scale);
  r.information = fromCity.transpose() * information * fromCity;
  r.informationGivenMap = fromCity.transpose() * givenMap * fromCity;
  r.mapSigma = o.mapSigma;
  r.covariance = toCity * covariance * toCity.transpose();
  if (r.status == MatchStatus::Rejected) return;
  if (r.observableDirections == 0) {
    r.status = MatchStatus::Rejected;
    r.reason = "the road points and curbs leave every direction unbounded or too uncertain";
  } else if (r.observableDirections < 3) {
    r.status = MatchStatus::Degenerate;
    r.reason = std::to_string(3 - r.observableDirections) + " unobservable direction(s)";
  } else {
    r.status = MatchStatus::Accepted;
    r.reason.clear();
  }
}

}  // namespace hdprior
