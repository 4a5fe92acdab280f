// Honest match uncertainty: how far the road points let the pose move (plausibleHalfWidths), and the
// information widened to it (widenToEvidence), on synthetic maps.
#include "engine/geom/angles.h"
#include "engine/match/match_uncertainty.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "../map/synthetic_maps.h"
#include "matcher_map.h"
#include "ring_road_points.h"
#include "engine/geom/se2.h"
#include "engine/map/hd_map.h"
#include "engine/match/map_matcher.h"

namespace hdprior {
namespace {

// A 10 m corridor seen kerb to kerb: the points pin the lateral place and yaw to a few decimetres
// and tenths of a degree, and leave the place along the corridor unbounded.
TEST(MatchUncertainty, AFullySeenCorridorBoundsLateralAndYawButNotAlong) {
  const HdMap map = test::matcherMap(test::mapOf({test::rectangle(-150, -5, 150, 5)}));
  const Eigen::Vector3d truth(3.0, 1.5, 0.05);
  const auto points = test::ringRoadPoints(map.drivable(), truth);
  const Eigen::Vector3d w = plausibleHalfWidths(map.boundaryDistance(), points, {}, truth, MatchOptions{});
  EXPECT_TRUE(std::isinf(w.x())) << w.transpose();
  EXPECT_LT(w.y(), 0.4);
  EXPECT_GT(w.y(), 0.05);
  EXPECT_LT(w.z(), 1.5 * kDegree);
}

// Road points on a 4 m strip down the middle of a 40 m wide road (what the lidar labels road on a
// wide street whose far lanes it calls other ground): every pose within metres fits, and the match
// must not claim otherwise.
TEST(MatchUncertainty, ANarrowStripInAWideRoadIsReportedUnobservable) {
  const HdMap map = test::matcherMap(test::mapOf({test::rectangle(-150, -20, 150, 20)}));
  const Eigen::Vector3d truth(0.0, 0.0, 0.0);
  std::vector<Eigen::Vector2d> strip;
  for (double x = -30.0; x <= 30.0; x += 0.2)
    for (double y = -2.0; y <= 2.0; y += 0.25) strip.emplace_back(x, y);
  const Eigen::Vector3d w = plausibleHalfWidths(map.boundaryDistance(), strip, {}, truth, MatchOptions{});
  EXPECT_TRUE(std::isinf(w.x()));
  EXPECT_TRUE(std::isinf(w.y()));
  EXPECT_TRUE(std::isinf(w.z()));
  MatchOptions o;
  o.timeBudgetMs = 1e6;
  MapMatcher matcher(map, o);
  const MatchResult r = matcher.match(strip, offsetPose(truth, {0.0, 1.0, 1.0 * kDegree}));
  EXPECT_EQ(r.status, MatchStatus::Rejected) << r.reason;
  EXPECT_EQ(r.observableDirections, 0);
  EXPECT_TRUE(r.information.isZero());
}

// Road points along one side of a 40 m road: they bound the pose towards that kerb only, so the
// lateral place is unbounded; the curb points where the lidar saw that kerb pin it.
TEST(MatchUncertainty, OneSidedRoadPointsNeedTheCurbToBoundTheLateralPlace) {
  const HdMap map = test::matcherMap(test::mapOf({test::rectangle(-150, -20, 150, 20)}));
  const Eigen::Vector3d truth(0.0, 0.0, 0.0);
  std::vector<Eigen::Vector2d> strip, curbs;
  for (int i = 0; i <= 300; ++i) {
    const double x = -30.0 + 0.2 * i;
    for (double y = -19.9; y <= -16.0; y += 0.25) strip.emplace_back(x, y);
    if (i % 5 == 0) curbs.emplace_back(x, -20.0);  // a curb point every metre
  }
  const Eigen::Vector3d roadOnly = plausibleHalfWidths(map.boundaryDistance(), strip, {}, truth, MatchOptions{});
  EXPECT_TRUE(std::isinf(roadOnly.y())) << roadOnly.transpose();
  const Eigen::Vector3d withCurbs = plausibleHalfWidths(map.boundaryDistance(), strip, curbs, truth, MatchOptions{});
  EXPECT_LT(withCurbs.y(), 0.6) << withCurbs.transpose();
  EXPECT_LT(withCurbs.z(), 1.5 * kDegree);
  EXPECT_TRUE(std::isinf(withCurbs.x()));
}

// The widened covariance: along each observed direction (here the estimate frame's axes) at least
// half-width / kappa, plus the map's error; a direction beyond its cap is dropped: degenerate.
TEST(MatchUncertainty, WideningRaisesSigmasToTheEvidenceAndDropsWhatExceedsTheCaps) {
  MatchOptions o;
  o.evidenceKappa = 2.0;
  o.mapSigma = 0.1;
  o.mapSigmaYawDeg = 0.0;
  MatchResult r;
  r.status = MatchStatus::Accepted;
  r.estimate = {5.0, 7.0, 0.5};
  // Laplace: along 0.02 m, lateral 0.03 m, yaw 0.05 deg in the estimate's frame.
  Eigen::Matrix3d local = Eigen::Matrix3d::Zero();
  const double sy = 0.05 * kDegree;
  local.diagonal() << 0.02 * 0.02, 0.03 * 0.03, sy * sy;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  R.topLeftCorner<2, 2>() << std::cos(0.5), -std::sin(0.5), std::sin(0.5), std::cos(0.5);
  r.covariance = R * local * R.transpose();
  r.information = r.covariance.inverse();
  widenToEvidence(Eigen::Vector3d(0.01, 0.4, 0.4 * kDegree), o, r);
  EXPECT_EQ(r.status, MatchStatus::Accepted);
  EXPECT_EQ(r.observableDirections, 3);
  const Eigen::Matrix3d c = R.transpose() * r.covariance * R;
  EXPECT_NEAR(std::sqrt(c(0, 0)), std::hypot(0.02, 0.1), 1e-9);   // Laplace beats the evidence, plus map
  EXPECT_NEAR(std::sqrt(c(1, 1)), std::hypot(0.2, 0.1), 1e-9);    // evidence 0.4 / 2, plus map
  EXPECT_NEAR(std::sqrt(c(2, 2)), 0.2 * kDegree, 1e-12);
  EXPECT_NEAR(c(1, 2), 0.0, 1e-15);
  EXPECT_TRUE((r.information * r.covariance).isApprox(Eigen::Matrix3d::Identity(), 1e-6));

  o.maxSigmaLateral = 0.15;
  r.status = MatchStatus::Accepted;
  r.covariance = R * local * R.transpose();
  r.information = r.covariance.inverse();
  widenToEvidence(Eigen::Vector3d(0.01, 0.4, 0.4 * kDegree), o, r);
  EXPECT_EQ(r.status, MatchStatus::Degenerate);
  EXPECT_EQ(r.observableDirections, 2);
  const Eigen::Vector3d lateral(-std::sin(0.5), std::cos(0.5), 0.0);
  EXPECT_LT((r.information * lateral).norm(), 1e-9 * r.information.norm());
}

// A match whose only observed direction is (nearly) yaw, and the evidence leaves yaw unbounded: after
// marginalising it nothing is left, not a rounding residue posing as a lateral prior.
TEST(MatchUncertainty, NothingIsLeftWhenTheOnlyObservedDirectionIsDropped) {
  MatchResult r;
  r.status = MatchStatus::Degenerate;
  r.estimate = {80.0, 740.0, -0.12};
  const Eigen::Vector3d v = Eigen::Vector3d(0.02, 0.05, 1.0).normalized();
  r.information = 1e5 * v * v.transpose();
  r.covariance = v * v.transpose() / 1e5;
  const double inf = std::numeric_limits<double>::infinity();
  widenToEvidence(Eigen::Vector3d(inf, 1.3, inf), MatchOptions{}, r);
  EXPECT_EQ(r.status, MatchStatus::Rejected) << r.reason;
  EXPECT_EQ(r.observableDirections, 0);
  EXPECT_TRUE(r.information.isZero(1e-12)) << r.information;
}

}  // namespace
}  // namespace hdprior
