// The HD-map aggregate loaded from the real log: every layer present and consistent with the
// ground-truth trajectory; a ground-height GeoTIFF in place of the .npy; synthetic maps.
#include "engine/map/hd_map.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/map_export.h"
#include "synthetic_maps.h"
#include "test_data.h"

namespace hdprior {
namespace {

HdMapOptions withNdtSizes(std::vector<double> sizes) {
  HdMapOptions o;
  o.ndtCellSizes = std::move(sizes);
  return o;
}

TEST(HdMap, RealLogLayersAgreeWithTheTrajectory) {
  const ArgoverseLog log(test::sharedLog());
  const HdMap map = HdMap::load(log.mapFiles(), withNdtSizes({1.0, 4.0, 2.0}));
  ASSERT_EQ(map.ndtGrids().size(), 3u);
  EXPECT_EQ(map.ndtGrids()[0].cellSize(), 4.0);
  EXPECT_EQ(map.ndtGrids()[2].cellSize(), 1.0);
  EXPECT_EQ(&map.ndtGrid(2.0), &map.ndtGrids()[1]);
  EXPECT_THROW(map.ndtGrid(3.0), Error);
  EXPECT_EQ(map.vectorMap().drivableAreas.size(), 13u);
  EXPECT_EQ(map.laneGraph().lanes().size(), 183u);
  size_t onRoad = 0, insideSdf = 0, withNdt = 0;
  const auto& poses = log.cityTEgo().poses();
  for (const SE3& T : poses) {
    const Eigen::Vector2d xy = T.translation().head<2>();
    onRoad += map.drivable().contains(xy);
    insideSdf += map.boundaryDistance().distance(xy) < 0.0;
    withNdt += map.ndtGrid(1.0).cellAt(xy) != nullptr;
    ASSERT_FALSE(std::isnan(map.groundHeight().heightAt(xy)));
  }
  EXPECT_EQ(onRoad, poses.size());  // the vehicle drives on the drivable area
  EXPECT_EQ(insideSdf, poses.size());
  EXPECT_EQ(withNdt, poses.size());
  EXPECT_TRUE(map.laneGraph().nearestLane(poses.front().translation().head<2>(), 3.0).has_value());
}

TEST(HdMap, GroundHeightFromAGeoTiffReplacesTheNpy) {
  const ArgoverseLog log(test::sharedLog());
  const HdMap fromNpy = HdMap::load(log.mapFiles(), withNdtSizes({}));
  const auto dir = test::freshOutputDir("hd_map_geotiff");
  exportMapGeoTiffs(fromNpy, dir);
  HdMapOptions options = withNdtSizes({});
  options.boundaryDistance = false;
  options.groundHeightGeoTiff = dir / "ground_height.tif";
  const HdMap fromTif = HdMap::load(log.mapFiles(), options);
  EXPECT_EQ(fromTif.groundHeight().source(), (dir / "ground_height.tif").string());
  EXPECT_FALSE(fromTif.hasBoundaryDistance());
  EXPECT_THROW(fromTif.boundaryDistance(), Error);
  for (const SE3& T : log.cityTEgo().poses()) {
    const Eigen::Vector2d xy = T.translation().head<2>();
    ASSERT_EQ(fromTif.groundHeight().heightAt(xy), fromNpy.groundHeight().heightAt(xy));
  }
}

TEST(HdMap, SyntheticMapWithoutGroundHeight) {
  const HdMap map = HdMap::build(test::mapOf({test::rectangle(0, 0, 20, 8)}), std::nullopt, {}, "town");
  EXPECT_FALSE(map.hasGroundHeight());
  EXPECT_THROW(map.groundHeight(), Error);
  EXPECT_NEAR(map.drivable().area(), 160.0, 1e-9);
  EXPECT_NEAR(map.boundaryDistance().distance({10, 4}), -4.0, 0.1);
  EXPECT_EQ(map.ndtGrid(1.0).validCellCount(), 160u);
  try {
    HdMap::build(VectorMap{}, std::nullopt, {}, "town.json");
    ADD_FAILURE() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), "town.json");
  }
}

}  // namespace
}  // namespace hdprior
