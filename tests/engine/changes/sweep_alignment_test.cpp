// A sweep whose kerbs meet the map only under a shift: a pose that is off moves the kerbs of both
// sides and of every polygon in view, a map change moves one polygon's; and the poses can be that
// far off only after a drive.
#include "engine/changes/sweep_alignment.h"

#include <gtest/gtest.h>

#include "engine/changes/synthetic_street.h"
#include "engine/map/ground_height.h"
#include "engine/map/synthetic_maps.h"

namespace hdprior {
namespace {

// Kerb points every 0.5 m along both kerbs of the straight street (y = +-5 m), x in [-20, 20].
LabelledSweep kerbsOfTheStreet() {
  LabelledSweep sweep;
  for (double x = -20; x <= 20; x += 0.5)
    for (double y : {-5.0, 5.0}) {
      sweep.points.emplace_back(x, y, 0.0);
      sweep.ground.push_back(1);
      sweep.road.push_back(kCurbPoint);
    }
  return sweep;
}

SE3 at(double x, double y) {
  SE3 pose = SE3::Identity();
  pose.translation() = Eigen::Vector3d(x, y, 0);
  return pose;
}

// The street as two polygons meeting at x = 0, both in view.
HdMap twoPolygonStreet() { return test::streetMap({test::rectangle(-100, -5, 0, 5), test::rectangle(0, -5, 100, 5)}); }

SweepAlignment alignment(const HdMap& map, const LabelledSweep& sweep, const SE3& pose) {
  return sweepAlignment(sweep, pose, map.boundaryDistance(), map.vectorMap().drivableAreas, nullptr, ChangeOptions{});
}

TEST(SweepAlignment, KerbsOnTheMapAtThePoseAreAligned) {
  const HdMap map = twoPolygonStreet();
  const SweepAlignment a = alignment(map, kerbsOfTheStreet(), at(0, 0));
  EXPECT_EQ(a.kerbs, 162);
  EXPECT_EQ(a.alignedAtPose, 162);
  EXPECT_EQ(a.alignedShifted, 162);
  EXPECT_LT(a.shift.norm(), 1e-9);
  EXPECT_FALSE(a.misaligned(ChangeOptions{}, 500.0));
}

TEST(SweepAlignment, APoseOffSidewaysMovesBothKerbsAndIsMisalignedOnlyAfterADriveThatCouldLoseThatMuch) {
  const HdMap map = twoPolygonStreet();
  const ChangeOptions o;
  const SweepAlignment a = alignment(map, kerbsOfTheStreet(), at(0, 2.5));
  EXPECT_EQ(a.alignedAtPose, 0);
  EXPECT_EQ(a.alignedShifted, 162);
  EXPECT_NEAR(a.shift.y(), -2.5, 0.26);
  EXPECT_EQ(a.polygonsShifted, 2);
  EXPECT_TRUE(a.misaligned(o, 200.0)) << "3 % of 200 m is 6 m";
  EXPECT_FALSE(a.misaligned(o, 50.0)) << "3 % of 50 m is 1.5 m: the map is off, not the pose";
}

TEST(SweepAlignment, AMovedBoundaryOnOneSideIsAMapChange) {
  const HdMap map = test::streetMap({test::rectangle(-100, -5, 0, 7.5), test::rectangle(0, -5, 100, 7.5)});
  const ChangeOptions o;
  const SweepAlignment a = alignment(map, kerbsOfTheStreet(), at(0, 0));
  EXPECT_EQ(a.alignedAtPose, 81);
  EXPECT_LE(a.alignedShifted, 81) << "a shift lines up one side or the other, never both";
  EXPECT_FALSE(a.misaligned(o, 500.0));
}

TEST(SweepAlignment, AShiftedPolygonThatFillsTheViewIsAMapChange) {
  // One polygon drawn 2.5 m off: its two kerbs line up under one shift, as with a pose 2.5 m off,
  // but nothing else in view says which moved.
  const HdMap map = test::streetMap({test::rectangle(-100, -7.5, 100, 2.5)});
  const SweepAlignment a = alignment(map, kerbsOfTheStreet(), at(0, 0));
  EXPECT_EQ(a.alignedShifted, 162);
  EXPECT_EQ(a.polygonsShifted, 1);
  EXPECT_FALSE(a.misaligned(ChangeOptions{}, 500.0));
}

TEST(SweepAlignment, AFewKerbsSayNothing) {
  const HdMap map = twoPolygonStreet();
  LabelledSweep few;
  for (double x : {-3.0, -1.0, 1.0, 3.0}) {
    few.points.emplace_back(x, 5.0, 0.0), few.ground.push_back(1), few.road.push_back(kCurbPoint);
    few.points.emplace_back(x, 0.0, 0.0), few.ground.push_back(1), few.road.push_back(kRoadPoint);
  }
  const SweepAlignment a = alignment(map, few, at(0, 2.5));
  EXPECT_EQ(a.kerbs, 4);
  EXPECT_FALSE(a.misaligned(ChangeOptions{}, 500.0));
}

// The road under the car `height` metres over a flat raster at 0 (1 m pixels over +-50 m): `n`
// road points on a ring of 6 m.
SweepAlignment overFlatGround(double height, int n) {
  Sim2 sim2;
  sim2.t = Eigen::Vector2d(50, 50);
  const GroundHeight flat(sim2, 100, 100, std::vector<float>(100 * 100, 0.0f), "flat");
  LabelledSweep sweep = kerbsOfTheStreet();
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    sweep.points.emplace_back(6 * std::cos(a), 6 * std::sin(a), height);
    sweep.ground.push_back(1);
    sweep.road.push_back(kRoadPoint);
  }
  const HdMap map = twoPolygonStreet();
  return sweepAlignment(sweep, at(0, 0), map.boundaryDistance(), map.vectorMap().drivableAreas, &flat, ChangeOptions{});
}

TEST(SweepAlignment, ARoadOffTheGroundHeightRasterIsAPoseErrorWhereverTheKerbsLie) {
  const ChangeOptions o;
  const SweepAlignment on = overFlatGround(0.1, 200);
  EXPECT_NEAR(on.roadOverRaster, 0.1, 1e-6);
  EXPECT_EQ(on.roadOnRaster, 200) << "the kerb points are not counted";
  EXPECT_FALSE(on.misaligned(o, 500.0));
  const SweepAlignment above = overFlatGround(0.4, 200), below = overFlatGround(-0.3, 200);
  EXPECT_EQ(above.alignedAtPose, above.kerbs) << "its kerbs are on the map";
  EXPECT_TRUE(above.offGround(o));
  EXPECT_TRUE(above.misaligned(o, 0.0));
  EXPECT_TRUE(below.misaligned(o, 0.0));
  EXPECT_FALSE(overFlatGround(0.4, 20).misaligned(o, 500.0)) << "20 road points are too few to tell";
}

}  // namespace
}  // namespace hdprior
