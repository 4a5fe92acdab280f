// Crossings judged by how much brighter the road is inside them than around it, against the road's
// own spread: painted, unpainted, unseen, a road too varied to tell, and paint the map lacks.
#include "engine/changes/crossing_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

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

// Ground every 0.1 m within `range` of the sensor (about 4,000 returns in the crossing), of brightness 1.
SweepPaint groundAround(double range) {
  SweepPaint paint;
  for (double x = -range; x <= range; x += 0.1)
    for (double y = -range; y <= range; y += 0.1)
      if (std::hypot(x, y) <= range) paint.road.emplace_back(x, y), paint.brightness.push_back(1.0f);
  return paint;
}

// Runs every 0.5 m along a line from a to b.
void addRunsAlong(SweepPaint& paint, const Vec2& a, const Vec2& b) {
  const int n = int((b - a).norm() / 0.5);
  for (int k = 0; k <= n; ++k) paint.runs.push_back({a + (b - a) * (double(k) / n), 4});
}

// A fixed number in [-1, 1) for a pair of integers.
double hashed(long a, long b) {
  uint32_t h = uint32_t(a * 73856093L) ^ uint32_t(b * 19349663L);
  h ^= h >> 13, h *= 0x5bd1e995u, h ^= h >> 15;
  return (h % 20000) / 10000.0 - 1.0;
}

// A street along x (x -30..30, y -6..6) with a road return every 0.1 m: asphalt of brightness 1
// that varies by up to +-`texture` from one `patch`-metre square to the next and by +-10 % from
// return to return, and paint 1.6 times as bright where `painted`.
SweepPaint street(const std::function<bool(const Vec2&)>& painted, double texture = 0.1, double patch = 1.0) {
  SweepPaint paint;
  for (long i = -300; i <= 300; ++i)
    for (long j = -60; j <= 60; ++j) {
      const Vec2 p(i * 0.1, j * 0.1);
      const double road = 1.0 + texture * hashed(long(std::floor(p.x() / patch)), long(std::floor(p.y() / patch)));
      paint.road.push_back(p);
      paint.brightness.push_back(float((painted(p) ? 1.6 : 1.0) * road * (1.0 + 0.1 * hashed(i, j))));
    }
  return paint;
}

// Zebra stripes half a metre wide across the street (|y| < 4), in a crossing from x0 to x0 + 3.
bool onStripe(const Vec2& p, double x0) {
  const double u = p.x() - x0;
  return std::abs(p.y()) < 4 && u > 0 && u < 3 && std::fmod(u, 1.0) > 0.25 && std::fmod(u, 1.0) < 0.75;
}

TEST(CrossingCheck, PaintedStripesMakeACrossingConsistent) {
  VectorMap map;
  map.pedestrianCrossings = {crossingAhead(7)};
  CrossingEvidence evidence(map, ChangeOptions{});
  SweepPaint paint = street([](const Vec2& p) { return onStripe(p, 5.0); });
  addRunsAlong(paint, {5.5, -4}, {5.5, 4});
  evidence.add(3, paint, SE3::Identity());
  const std::vector<CrossingVerdict> verdicts = evidence.verdicts();
  ASSERT_EQ(verdicts.size(), 1u);
  const CrossingVerdict& v = verdicts[0];
  EXPECT_EQ(v.id, 7);
  EXPECT_EQ(v.verdict, MapVerdict::Consistent);
  EXPECT_GT(v.confidence, 0.95);
  EXPECT_NEAR(v.brightness.lift(), 0.3, 0.05) << "half the crossing painted 1.6x";
  EXPECT_GT(v.brightness.insideCells, 300);
  EXPECT_GE(v.controls, 5) << "its outline moved along the street, on bare road";
  EXPECT_GT(v.brightness.spread, 0.0);
  EXPECT_LT(v.brightness.spread, 0.05);
  EXPECT_GT(v.paintCells, 10) << "the runs are tallied too, for the map's paint layer";
  EXPECT_EQ(v.bestFrame, 3);
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
  CrossingEvidence seen(map, ChangeOptions{});
  seen.add(0, street([](const Vec2& p) { return onStripe(p, -8.0); }), SE3::Identity());
  const std::vector<CrossingVerdict> v = seen.verdicts();
  EXPECT_EQ(v[0].verdict, MapVerdict::Contradicted);
  EXPECT_GT(v[0].confidence, 0.95);
  EXPECT_NEAR(v[0].paintedLift, 0.3, 0.05) << "the painted crossing's lift, which this one lacks";
  EXPECT_EQ(v[1].verdict, MapVerdict::Consistent);

  // Where no crossing shows paint, the paint may be too faint to see: nothing is contradicted.
  CrossingEvidence faint(map, ChangeOptions{});
  faint.add(0, street([](const Vec2&) { return false; }), SE3::Identity());
  EXPECT_EQ(faint.verdicts()[0].verdict, MapVerdict::Unobserved);
  EXPECT_EQ(faint.verdicts()[1].verdict, MapVerdict::Unobserved);

  // A metre of one ring across the first crossing is too little to tell.
  CrossingEvidence glimpsed(map, ChangeOptions{});
  SweepPaint few = street([](const Vec2& p) { return onStripe(p, -8.0); });
  SweepPaint kept;
  for (size_t i = 0; i < few.road.size(); ++i) {
    const Vec2& p = few.road[i];
    const bool inFirst = p.x() > 4 && p.x() < 9 && std::abs(p.y()) < 5;
    if (!inFirst || (std::abs(p.x() - 6.0) < 0.05 && std::abs(p.y()) < 0.5)) kept.road.push_back(p), kept.brightness.push_back(few.brightness[i]);
  }
  glimpsed.add(0, kept, SE3::Identity());
  EXPECT_EQ(glimpsed.verdicts()[1].verdict, MapVerdict::Consistent);
  EXPECT_EQ(glimpsed.verdicts()[0].verdict, MapVerdict::Unobserved);
  EXPECT_EQ(glimpsed.verdicts()[0].confidence, 0.0);
}

// A road whose brightness varies over metre squares as much as paint lifts a crossing: the lift
// is within the road's own spread, and no verdict is given.
TEST(CrossingCheck, ARoadThatVariesAsMuchAsPaintLeavesCrossingsUnobserved) {
  VectorMap map;
  map.pedestrianCrossings = {crossingAhead(7), crossingBehind(8)};
  CrossingEvidence evidence(map, ChangeOptions{});
  evidence.add(0, street([](const Vec2& p) { return onStripe(p, -8.0); }, 0.6, 3.0), SE3::Identity());
  const std::vector<CrossingVerdict> v = evidence.verdicts();
  EXPECT_GT(v[0].brightness.spread, 0.15);
  EXPECT_EQ(v[0].verdict, MapVerdict::Unobserved);
  EXPECT_EQ(v[1].verdict, MapVerdict::Unobserved);
}

TEST(CrossingCheck, TheSweepsPoseCarriesItsPaintIntoTheCity) {
  VectorMap map;
  PedestrianCrossing c = crossingAhead(7);
  for (Eigen::Vector3d& p : c.edge1) p.x() += 100;
  for (Eigen::Vector3d& p : c.edge2) p.x() += 100;
  map.pedestrianCrossings = {c};
  CrossingEvidence evidence(map, ChangeOptions{});
  const SweepPaint paint = street([](const Vec2& p) { return onStripe(p, 5.0); });
  evidence.add(0, paint, SE3::Identity());  // the crossing is 100 m away: nothing seen
  EXPECT_EQ(evidence.verdicts()[0].brightness.insideCells, 0);
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

// Asphalt with a bright patch (2.5x) in 5 % of its quarter-metre cells: a crossing is judged
// against the road's spread, so the patches neither paint an unpainted crossing nor hide a painted one.
TEST(CrossingCheck, AsphaltPatchesAreTheRoadsSpreadNotACrossing) {
  VectorMap map;
  map.pedestrianCrossings = {crossingAhead(7), crossingBehind(8)};
  for (const bool painted : {true, false}) {
    CrossingEvidence evidence(map, ChangeOptions{});
    SweepPaint paint = street([&](const Vec2& p) { return onStripe(p, -8.0) || (painted && onStripe(p, 5.0)); });
    for (size_t i = 0; i < paint.road.size(); ++i)
      if (hashed(long(std::floor(paint.road[i].x() * 4)), long(std::floor(paint.road[i].y() * 4)) + 7) > 0.9) paint.brightness[i] *= 2.5f;
    for (int frame = 0; frame < 3; ++frame) evidence.add(frame, paint, SE3::Identity());
    const CrossingVerdict v = evidence.verdicts()[0];
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
