// A stale map: the road points of a street the map no longer has are left out region by region, and
// the rest still match (issue 16: "reject per region, not per keyframe").
#include "engine/match/stale_regions.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../map/synthetic_maps.h"
#include "matcher_map.h"
#include "ring_road_points.h"
#include "engine/eval/match_calibration.h"
#include "engine/geom/angles.h"
#include "engine/geom/se2.h"
#include "engine/map/hd_map.h"
#include "engine/match/map_matcher.h"

namespace hdprior {
namespace {

TEST(StaleRegions, AreasMissingFromTheMapAreLeftOutAndTheRestStillMatches) {
  // The world: a corridor with a drivable lot on each side (3-4 m of kerb and sidewalk between);
  // the map: the corridor alone.
  const HdMap world = test::matcherMap(test::mapOf({test::rectangle(-150, -5, 150, 5), test::rectangle(-25, 8, 25, 45),
                                            test::rectangle(-25, -45, 25, -9)}));
  const HdMap stale = test::matcherMap(test::mapOf({test::rectangle(-150, -5, 150, 5)}));
  const Eigen::Vector3d truth(0.0, 0.0, 0.0);
  const std::vector<Eigen::Vector2d> points = test::ringRoadPoints(world.drivable(), truth);

  const RegionSelection s = pointsInAgreeingRegions(stale.boundaryDistance(), points, {}, truth, MatchOptions{});
  EXPECT_GT(s.droppedRegions, 0u);
  EXPECT_GT(s.droppedPoints, points.size() / 2);
  for (const Eigen::Vector2d& p : s.road) EXPECT_LT(std::abs(p.y()), 12.0) << "a point of a missing lot was kept";

  MatchOptions o;
  o.timeBudgetMs = 1e6;
  const Eigen::Vector3d start = offsetPose(truth, {0.0, 0.8, 0.02});
  MatchOptions keepAll = o;
  keepAll.staleShare = 1.0;  // no region can have more than all its points far: every point is kept
  const MatchResult whole = MapMatcher(stale, keepAll).match(points, start);
  EXPECT_EQ(whole.staleRegionPoints, 0u);
  EXPECT_EQ(whole.status, MatchStatus::Rejected) << "inliers " << whole.inlierRatio;
  const MatchResult regional = MapMatcher(stale, o).match(points, start);
  EXPECT_EQ(regional.status, MatchStatus::Degenerate) << regional.reason << " " << regional.evidenceHalfWidths.transpose();
  EXPECT_GT(regional.staleRegionPoints, points.size() / 2);
  const MatchErrorSample e = matchErrorSample(truth, regional.estimate, regional.information);
  EXPECT_LT(std::abs(e.error(1)), 0.1);
  EXPECT_LT(std::abs(e.error(2)), 0.3 * kDegree);
  EXPECT_TRUE(std::isinf(e.sigma(0)));  // along the corridor: unobservable
  EXPECT_LT(e.sigma(1), 0.3);
}

// Where the map agrees everywhere nothing is left out.
TEST(StaleRegions, AnUpToDateMapKeepsEveryPoint) {
  const HdMap map = test::matcherMap(test::mapOf({test::rectangle(-150, -5, 150, 5), test::rectangle(-12, 5, 12, 40)}));
  const Eigen::Vector3d truth(1.0, -0.5, 0.02);
  const std::vector<Eigen::Vector2d> points = test::ringRoadPoints(map.drivable(), truth);
  const RegionSelection s = pointsInAgreeingRegions(map.boundaryDistance(), points, points, offsetPose(truth, {0.5, 1.0, 0.02}), MatchOptions{});
  EXPECT_EQ(s.droppedPoints, 0u);
  EXPECT_EQ(s.road.size(), points.size());
  EXPECT_EQ(s.curbs.size(), points.size());
}

}  // namespace
}  // namespace hdprior
