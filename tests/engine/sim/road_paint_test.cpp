// Paint on the ray-cast road: lane lines by mark type, zebra crossings, and brighter returns
// where a simulated sweep falls on them.
#include "engine/sim/road_paint.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/io/vector_map.h"
#include "engine/sim/crosswalk_sites.h"
#include "engine/sim/lidar_model.h"
#include "engine/sim/scene_builder.h"
#include "engine/sim/sweep_simulator.h"
#include "town_route.h"

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;

LaneSegment laneAlongX(const std::string& left, const std::string& right) {
  LaneSegment lane;
  lane.id = 1;
  lane.leftLaneBoundary = {{0, 2, 0}, {30, 2, 0}};
  lane.rightLaneBoundary = {{0, -2, 0}, {30, -2, 0}};
  lane.leftLaneMarkType = left;
  lane.rightLaneMarkType = right;
  return lane;
}

TEST(RoadPaint, LaneLinesFollowTheirMarkTypes) {
  VectorMap map;
  map.laneSegments.push_back(laneAlongX("DOUBLE_SOLID_YELLOW", "DASHED_WHITE"));
  const RoadPaint paint(map, Vec2(-10, -10), Vec2(40, 10));
  const PaintOptions o;
  // Double yellow: two lines either side of y = 2, a gap on it.
  EXPECT_EQ(paint.reflectivityAt(Vec2(5, 2.135)), o.yellow);
  EXPECT_EQ(paint.reflectivityAt(Vec2(5, 1.865)), o.yellow);
  EXPECT_EQ(paint.reflectivityAt(Vec2(5, 2.0)), 0);
  EXPECT_EQ(paint.reflectivityAt(Vec2(5, 2.4)), 0);
  // Dashed white: 3 m of paint, 9 m without.
  EXPECT_EQ(paint.reflectivityAt(Vec2(1.5, -2.0)), o.white);
  EXPECT_EQ(paint.reflectivityAt(Vec2(13.5, -2.05)), o.white);
  EXPECT_EQ(paint.reflectivityAt(Vec2(6.0, -2.0)), 0);
  EXPECT_EQ(paint.reflectivityAt(Vec2(6.0, -2.1)), 0);
  EXPECT_EQ(paint.reflectivityAt(Vec2(1.5, -1.9)), 0);  // 0.15 m wide

  VectorMap none;
  none.laneSegments.push_back(laneAlongX("NONE", "UNKNOWN"));
  EXPECT_EQ(RoadPaint(none, Vec2(-10, -10), Vec2(40, 10)).markCount(), 0u);
}

TEST(RoadPaint, WornPaintLeavesTheSameShareOfCellsBareInEverySweep) {
  VectorMap map;
  map.laneSegments.push_back(laneAlongX("SOLID_WHITE", "NONE"));
  PaintOptions o;
  o.wear = 0.3;
  o.wearSeed = 7;
  const RoadPaint paint(map, Vec2(-10, -10), Vec2(40, 10), o);
  int painted = 0, bare = 0;
  for (double x = 0.5; x < 29.5; x += 0.01) {
    const uint8_t r = paint.reflectivityAt(Vec2(x, 2.0));
    ASSERT_EQ(r, paint.reflectivityAt(Vec2(x, 2.0)));  // the same place the same every time
    (r == o.white ? painted : bare) += 1;
    ASSERT_TRUE(r == 0 || r == o.white);
  }
  EXPECT_NEAR(double(bare) / (painted + bare), 0.3, 0.1);
}

TEST(RoadPaint, CrossingsAreZebraStripesAcrossThem) {
  VectorMap map;
  PedestrianCrossing c;
  c.id = 1;
  c.edge1 = {{0, 0, 0}, {0, 10, 0}};  // across a street along x
  c.edge2 = {{3, 0, 0}, {3, 10, 0}};
  map.pedestrianCrossings.push_back(c);
  const RoadPaint paint(map, Vec2(-10, -10), Vec2(20, 20));
  for (double x : {0.2, 1.5, 2.8}) {
    EXPECT_EQ(paint.reflectivityAt(Vec2(x, 0.25)), PaintOptions{}.white);  // stripe 0..0.5
    EXPECT_EQ(paint.reflectivityAt(Vec2(x, 0.75)), 0);                     // gap 0.5..1
    EXPECT_EQ(paint.reflectivityAt(Vec2(x, 9.25)), PaintOptions{}.white);
  }
  EXPECT_EQ(paint.reflectivityAt(Vec2(3.2, 0.25)), 0);
  EXPECT_EQ(paint.reflectivityAt(Vec2(-0.2, 0.25)), 0);
}

// A town, a route through it and one sweep taken near a crossing: returns on its stripes are
// brighter than the plain road around it; labels stay road.
TEST(RoadPaint, ASweepIsBrighterOnTheStripesThanOnTheRoadBeside) {
  const test::TownRoute t(7, 1, 30.0);
  const TownMap& town = t.town;
  const PoseTrajectory& route = t.route;
  // The first moment the drive is 8-15 m from a crossing's centre.
  int64_t at = -1;
  for (int64_t t = route.startNs(); t < route.endNs() && at < 0; t += 100'000'000)
    for (const PedestrianCrossing& c : town.vectorMap.pedestrianCrossings) {
      const Vec2 centre = 0.25 * (c.edge1[0] + c.edge1[1] + c.edge2[0] + c.edge2[1]).head<2>();
      const double d = (route.at(t).translation().head<2>() - centre).norm();
      if (d > 8.0 && d < 15.0) at = t;
    }
  ASSERT_GE(at, 0) << "the route passes no crossing";
  const Scene scene = buildScene(town.vectorMap, t.ground, t.lanes, t.path, route.startNs(), {}, 1, "town");
  const SimulatedSweep sweep = simulateSweep(scene, argoverseLikeLidar(), route, at, SweepNoise{0.0, 0.0}, 1);
  const SE3 cityTEgo = route.at(at);
  const RoadPaint& paint = scene.paint();
  double striped = 0.0, plain = 0.0;
  size_t nStriped = 0, nPlain = 0;
  for (size_t i = 0; i < sweep.sweep.points.size(); ++i) {
    const LidarPoint& p = sweep.sweep.points[i];
    if (sweep.labels[i] != uint8_t(PointLabel::Road)) continue;
    const Vec2 xy = (cityTEgo * Eigen::Vector3d(p.x, p.y, p.z)).head<2>();
    if ((xy - cityTEgo.translation().head<2>()).norm() > 25.0) continue;
    // Away from the edges of the marks (float16 positions, motion), on paint or clear of it.
    bool allPaint = true, noPaint = true;
    for (const Vec2& d : {Vec2(0, 0), Vec2(0.1, 0), Vec2(-0.1, 0), Vec2(0, 0.1), Vec2(0, -0.1)}) {
      const bool painted = paint.reflectivityAt(xy + d) > 0;
      allPaint &= painted;
      noPaint &= !painted;
    }
    bool onCrossing = false, nearCrossing = false;
    for (const PedestrianCrossing& c : town.vectorMap.pedestrianCrossings) {
      const Ring2 outline = crossingOutline(c);
      onCrossing |= ringContains(outline, xy);
      nearCrossing |= polylineDistance(std::span(&xy, 1), outline, true) < 5.0;
    }
    if (onCrossing && allPaint) striped += p.intensity, ++nStriped;
    if ((onCrossing || nearCrossing) && noPaint) plain += p.intensity, ++nPlain;
  }
  ASSERT_GT(nStriped, 50u);
  ASSERT_GT(nPlain, 50u);
  std::printf("[ info ] %zu returns on paint: mean intensity %.1f; %zu on plain road: %.1f\n", nStriped,
              striped / double(nStriped), nPlain, plain / double(nPlain));
  EXPECT_GT(striped / double(nStriped), 3.0 * plain / double(nPlain));
}

}  // namespace
}  // namespace hdprior
