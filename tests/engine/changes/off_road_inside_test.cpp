// Ground off the road inside the drivable area: a polygon drawn over a sidewalk is contradicted; a
// cross street the road walk did not go into (asphalt) and a raised island the map paints over
// (road all round it) are not.
#include "engine/changes/off_road_inside.h"

#include <gtest/gtest.h>

#include "engine/changes/map_change_report.h"
#include "engine/changes/synthetic_street.h"

namespace hdprior {
namespace {

TEST(OffRoadInside, APolygonDrawnOverTheSidewalkIsContradictedWhereItsGroundIsNotRoad) {
  // The street's own polygon, and an 8 m x 15 m one over the north sidewalk (the world has none).
  const HdMap map = test::streetMap({test::rectangle(-100, -5, 100, 5), test::rectangle(-4, 5, 4, 20)});
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(test::straightStreet), map, ChangeOptions{});
  ASSERT_EQ(r.offRoad.size(), 1u);
  const OffRoadInside& o = r.offRoad[0];
  EXPECT_EQ(o.areaId, 2);
  EXPECT_NEAR(o.brightness, 2.5, 0.01);
  EXPECT_GE(o.region.depth, 2.9);  // the strip is 8 m wide: 4 m at its middle, less the cell
  EXPECT_GT(o.region.area, 40.0);
  ASSERT_EQ(r.drivableAreas.size(), 2u);
  EXPECT_EQ(r.drivableAreas[0].verdict, MapVerdict::Consistent);
  EXPECT_EQ(r.drivableAreas[1].verdict, MapVerdict::Contradicted);
  EXPECT_GT(r.drivableAreas[1].confidence, 0.5);
}

TEST(OffRoadInside, ACrossStreetTheWalkDidNotGoIntoIsAsphaltAndNoChange) {
  auto world = [](double x, double y) {
    test::GroundPoint g = test::straightStreet(x, y);
    if (y > 0 && std::abs(x) < 4.0) g = {true, std::abs(y) < 5.0, false};  // road on, not walked beyond the street
    return g;
  };
  const HdMap map = test::streetMap({test::rectangle(-100, -5, 100, 5), test::rectangle(-4, 5, 4, 20)});
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(world), map, ChangeOptions{});
  EXPECT_TRUE(r.offRoad.empty());
  EXPECT_NE(r.drivableAreas[1].verdict, MapVerdict::Contradicted);
}

TEST(OffRoadInside, ARaisedIslandTheMapPaintsOverIsNoChange) {
  // A wide road with a 6 m x 6 m island 7 m in from the polygon's boundary.
  auto world = [](double x, double y) {
    const bool island = std::abs(x) < 3.0 && std::abs(y - 10.0) < 3.0;
    return test::GroundPoint{!island, !island, false};
  };
  const HdMap map = test::streetMap({test::rectangle(-100, -20, 100, 20)});
  const MapChangeReport r = judgeMapChanges(test::streetEvidence(world), map, ChangeOptions{});
  EXPECT_TRUE(r.offRoad.empty());
}

TEST(OffRoadInside, WithoutBrightnessNothingIsSaid) {
  // The evidence without brightness (a grid built before it was read, or a sensor without intensity).
  const HdMap map = test::streetMap({test::rectangle(-100, -5, 100, 5), test::rectangle(-4, 5, 4, 20)});
  SurfaceEvidence plain(test::streetEvidence(test::straightStreet).geometry());
  LabelledSweep sweep;
  for (double x = -19.95; x < 20; x += 0.1)
    for (double y = -19.95; y < 20; y += 0.1) {
      const test::GroundPoint g = test::straightStreet(x, y);
      sweep.points.emplace_back(x, y, g.road ? 0.0 : 0.15);
      sweep.ground.push_back(1);
      sweep.road.push_back(g.kerb ? kCurbPoint : g.walked ? kRoadPoint : 0);
    }
  plain.add(0, sweep, SE3::Identity(), nullptr);
  const MapChangeReport r = judgeMapChanges(std::move(plain), map, ChangeOptions{});
  EXPECT_TRUE(r.offRoad.empty());
}

}  // namespace
}  // namespace hdprior
