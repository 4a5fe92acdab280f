// Crossings judged by the paint near the lidar: painted, unpainted, unseen, and paint the map lacks.
#include "engine/changes/crossing_check.h"

#include <gtest/gtest.h>

#include "engine/geom/polygon2d.h"

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;

// A crossing 3 m deep (x 5..8) across a street (y -4..4), as the Argoverse maps draw one.
PedestrianCrossing crossingAhead(int64_t id) {
  PedestrianCrossing c;
  c.id = id;
  c.edge1 = {{5, -4, 0}, {5, 4, 0}};
  c.edge2 = {{8, -4, 0}, {8, 4, 0}};
  return c;
}

// Ground every 0.1 m within `range` of the sensor (about 4,000 returns in the crossing).
SweepPaint groundAround(double range) {
  SweepPaint paint;
  for (double x = -range; x <= range; x += 0.1)
    for (double y = -range; y <= range; y += 0.1)
      if (std::hypot(x, y) <= range) paint.road.emplace_back(x, y);
  return paint;
}

// Runs every 0.5 m along a line from a to b.
void addRunsAlong(SweepPaint& paint, const Vec2& a, const Vec2& b) {
  const int n = int((b - a).norm() / 0.5);
  for (int k = 0; k <= n; ++k) paint.runs.push_back({a + (b - a) * (double(k) / n), 4});
}

TEST(CrossingCheck, PaintedEdgesMakeACrossingConsistent) {
  VectorMap map;
  map.pedestrianCrossings = {crossingAhead(7)};
  CrossingEvidence evidence(map, ChangeOptions{});
  SweepPaint paint = groundAround(12.0);
  addRunsAlong(paint, {5.1, -4}, {5.1, 4});
  addRunsAlong(paint, {7.9, -4}, {7.9, 4});
  evidence.add(3, paint, SE3::Identity());
  const std::vector<CrossingVerdict> verdicts = evidence.verdicts();
  ASSERT_EQ(verdicts.size(), 1u);
  EXPECT_EQ(verdicts[0].id, 7);
  EXPECT_EQ(verdicts[0].verdict, MapVerdict::Consistent);
  EXPECT_GT(verdicts[0].confidence, 0.95);
  EXPECT_EQ(verdicts[0].paintCells, 34);
  EXPECT_EQ(verdicts[0].bestFrame, 3);
  EXPECT_TRUE(evidence.missing().empty());
}

// The same crossing behind the sensor (x -8..-5).
PedestrianCrossing crossingBehind(int64_t id) {
  PedestrianCrossing c = crossingAhead(id);
  for (Eigen::Vector3d& p : c.edge1) p.x() -= 13;
  for (Eigen::Vector3d& p : c.edge2) p.x() -= 13;
  return c;
}

TEST(CrossingCheck, AWellSeenCrossingWithoutPaintIsContradictedWhereOthersShowPaint) {
  VectorMap map;
  map.pedestrianCrossings = {crossingAhead(7), crossingBehind(8)};
  SweepPaint paint = groundAround(12.0);
  addRunsAlong(paint, {-7.9, -4}, {-7.9, 4});
  addRunsAlong(paint, {-5.1, -4}, {-5.1, 4});
  CrossingEvidence seen(map, ChangeOptions{});
  seen.add(0, paint, SE3::Identity());
  EXPECT_EQ(seen.verdicts()[0].verdict, MapVerdict::Contradicted);
  EXPECT_GT(seen.verdicts()[0].roadCells, 500);
  EXPECT_EQ(seen.verdicts()[1].verdict, MapVerdict::Consistent);

  // Where no crossing shows paint, the paint may be too faint to see: nothing is contradicted.
  CrossingEvidence faint(map, ChangeOptions{});
  faint.add(0, groundAround(12.0), SE3::Identity());
  EXPECT_EQ(faint.verdicts()[0].verdict, MapVerdict::Unobserved);
  EXPECT_EQ(faint.verdicts()[1].verdict, MapVerdict::Unobserved);

  CrossingEvidence glimpsed(map, ChangeOptions{});
  SweepPaint few = paint;
  few.road.clear();
  for (double y = -0.5; y <= 0.5; y += 0.1) few.road.emplace_back(6.0, y);  // a metre of one ring across the first
  for (double x = -8; x <= -5; x += 0.1)
    for (double y = -4; y <= 4; y += 0.1) few.road.emplace_back(x, y);
  glimpsed.add(0, few, SE3::Identity());
  EXPECT_EQ(glimpsed.verdicts()[1].verdict, MapVerdict::Consistent);
  EXPECT_EQ(glimpsed.verdicts()[0].verdict, MapVerdict::Unobserved);
  EXPECT_EQ(glimpsed.verdicts()[0].confidence, 0.0);
}

TEST(CrossingCheck, TheSweepsPoseCarriesItsPaintIntoTheCity) {
  VectorMap map;
  PedestrianCrossing c = crossingAhead(7);
  for (Eigen::Vector3d& p : c.edge1) p.x() += 100;
  for (Eigen::Vector3d& p : c.edge2) p.x() += 100;
  map.pedestrianCrossings = {c};
  CrossingEvidence evidence(map, ChangeOptions{});
  SweepPaint paint = groundAround(12.0);
  addRunsAlong(paint, {5.1, -4}, {5.1, 4});
  addRunsAlong(paint, {7.9, -4}, {7.9, 4});
  evidence.add(0, paint, SE3::Identity());  // the crossing is 100 m away: nothing seen
  EXPECT_EQ(evidence.verdicts()[0].roadCells, 0);
  SE3 moved = SE3::Identity();
  moved.translation().x() = 100;
  evidence.add(1, paint, moved);
  EXPECT_EQ(evidence.verdicts()[0].verdict, MapVerdict::Consistent);
}

TEST(CrossingCheck, PaintTheMapLacksIsAMissingCrossingButLaneLinesAndStopLinesAreNot) {
  VectorMap map;
  LaneSegment lane;
  lane.leftLaneBoundary = {{-12, 2, 0}, {12, 2, 0}};
  lane.leftLaneMarkType = "SOLID_WHITE";
  lane.rightLaneBoundary = {{-12, -2, 0}, {12, -2, 0}};
  lane.rightLaneMarkType = "NONE";
  map.laneSegments = {lane};
  CrossingEvidence evidence(map, ChangeOptions{});
  SweepPaint paint = groundAround(12.0);
  addRunsAlong(paint, {-10, 2.05}, {10, 2.05});  // the mapped white line
  addRunsAlong(paint, {-8, -4}, {-8, 4});        // a stop line: one line, no depth
  for (double x = 5.25; x < 8.5; x += 1.0) addRunsAlong(paint, {x, -4}, {x, 4});  // zebra stripes, 3 m deep
  evidence.add(0, paint, SE3::Identity());
  const std::vector<MissingCrossing> missing = evidence.missing();
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_TRUE(ringContains(missing[0].outline, {6.5, 0}));
  EXPECT_FALSE(ringContains(missing[0].outline, {-8, 0}));
  EXPECT_GT(signedArea(missing[0].outline), 20.0);
  EXPECT_GT(missing[0].confidence, 0.95);
  EXPECT_EQ(missing[0].bestFrame, 0);
  // The painted cells the checks read: the line's on the map's paint, the stop line's and stripes' off it.
  int onLine = 0, offMap = 0;
  for (const PaintedCell& c : evidence.paintedCells()) {
    if (std::abs(c.centre.y() - 2.0) < 1.0) {
      EXPECT_TRUE(c.onMapPaint) << c.centre.transpose();
      ++onLine;
    }
    if (std::abs(c.centre.y()) < 0.5) {
      EXPECT_FALSE(c.onMapPaint) << c.centre.transpose();
      ++offMap;
    }
  }
  EXPECT_GE(onLine, 60);
  EXPECT_GE(offMap, 5);
}

// Asphalt with a bright patch in 5 % of its quarter-metre cells (a fixed hash), a crossing (x 5..8)
// whose stripes show in a third of its cells when `painted`, and one behind (x -8..-5) that always shows.
SweepPaint patchyRoad(bool painted) {
  SweepPaint paint = groundAround(12.0);
  for (double x = -11.875; x < 12; x += 0.25)
    for (double y = -11.875; y < 12; y += 0.25) {
      if (std::hypot(x, y) > 12.0) continue;
      const uint32_t hash = uint32_t(std::lround(x * 4 + 100) * 7919 + std::lround(y * 4 + 100) * 104729) % 1000;
      const bool inCrossing = x > 5 && x < 8 && std::abs(y) < 4, inOther = x > -8 && x < -5 && std::abs(y) < 4;
      if (inCrossing ? (painted && hash < 330) || hash < 50 : inOther ? hash < 330 : hash < 50) paint.runs.push_back({{x, y}, 4});
    }
  return paint;
}

TEST(CrossingCheck, AsphaltPatchesAreTheLogsBackgroundNotACrossing) {
  VectorMap map;
  map.pedestrianCrossings = {crossingAhead(7), crossingBehind(8)};
  for (const bool painted : {true, false}) {
    CrossingEvidence evidence(map, ChangeOptions{});
    for (int frame = 0; frame < 3; ++frame) evidence.add(frame, patchyRoad(painted), SE3::Identity());
    const CrossingVerdict v = evidence.verdicts()[0];
    EXPECT_NEAR(v.asphaltShare, 0.05, 0.015);
    EXPECT_EQ(v.verdict, painted ? MapVerdict::Consistent : MapVerdict::Contradicted) << painted;
    EXPECT_TRUE(evidence.missing().empty()) << painted;
  }
}

// A road return `range` metres from the lidar at `azimuth`, on ring `ring`.
void addRoadReturn(LidarSweep& sweep, LabelledSweep& labelled, double range, double azimuth, uint8_t intensity, uint8_t ring) {
  const Eigen::Vector3d p(range * std::cos(azimuth), range * std::sin(azimuth), -1.8);
  sweep.points.push_back({float(p.x()), float(p.y()), float(p.z()), intensity, ring, 0});
  labelled.points.push_back(p);
  labelled.ground.push_back(1);
  labelled.road.push_back(1);
}

TEST(SweepPaint, ARunIsThreeBrightReturnsOfOneRingInARow) {
  LidarSweep sweep;
  LabelledSweep labelled;
  // Ring 5 at 8 m, a return every 2 cm of arc; intensity 6, bright (40) from the 50th to the 54th.
  // Ring 6 has two bright returns only; a point beyond the range is never counted.
  for (int k = 0; k < 100; ++k) addRoadReturn(sweep, labelled, 8.0, k * 0.0025, k >= 50 && k < 55 ? 40 : 6, 5);
  for (int k = 0; k < 100; ++k) addRoadReturn(sweep, labelled, 10.0, k * 0.002, k == 10 || k == 11 ? 40 : 6, 6);
  addRoadReturn(sweep, labelled, 20.0, 0.0, 40, 7);
  const SweepPaint paint = findSweepPaint(sweep, labelled, ChangeOptions{});
  EXPECT_EQ(paint.road.size(), 200u);
  ASSERT_EQ(paint.runs.size(), 1u);
  EXPECT_EQ(paint.runs[0].points, 5);
  EXPECT_NEAR(paint.runs[0].centre.norm(), 8.0, 1e-3);
  EXPECT_NEAR(std::atan2(paint.runs[0].centre.y(), paint.runs[0].centre.x()), 52 * 0.0025, 1e-3);
}

// A far ring meets the road at a grazing angle and returns less from asphalt and paint alike:
// paint twice as bright as its asphalt is paint, though the near rings' asphalt is as bright as it.
TEST(SweepPaint, EachRingIsReadAgainstItsOwnAsphalt) {
  LidarSweep sweep;
  LabelledSweep labelled;
  for (int ring = 0; ring < 3; ++ring)
    for (int k = 0; k < 200; ++k) addRoadReturn(sweep, labelled, 4.0 + ring, k * 0.005, k == 100 ? 21 : 12, uint8_t(ring));
  for (int k = 0; k < 200; ++k) addRoadReturn(sweep, labelled, 10.0, k * 0.002, k >= 100 && k < 110 ? 12 : 6, 9);
  const SweepPaint paint = findSweepPaint(sweep, labelled, ChangeOptions{});
  ASSERT_EQ(paint.runs.size(), 1u);  // the near rings' bright flecks are single returns below 1.7x their asphalt
  EXPECT_EQ(paint.runs[0].points, 10);
  EXPECT_NEAR(paint.runs[0].centre.norm(), 10.0, 1e-3);
}

}  // namespace
}  // namespace hdprior
