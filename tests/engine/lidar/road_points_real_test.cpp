// Ground and road points on the real sweeps of the shared log, checked against the HD map
// placed with the ground-truth pose: ground points should lie on the ground-height raster,
// road points inside the drivable area, and most true road returns should be found.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/io/argoverse_log.h"
#include "engine/lidar/ground_segmentation.h"
#include "engine/lidar/road_points.h"
#include "engine/lidar/sweep_points.h"
#include "engine/map/hd_map.h"
#include "test_data.h"

namespace hdprior {
namespace {

struct Proxies {
  double groundPrecision = 0, groundRecall = 0, roadPrecision = 0, roadRecall = 0;
  size_t ground = 0, road = 0;
};

// "True ground": within 0.15 m of the ground-height raster once placed with the GT pose.
Proxies measure(const ArgoverseLog& log, const HdMap& map, size_t sweepIndex) {
  const std::vector<Eigen::Vector3d> points = sweepPoints(*log.sweep(sweepIndex));
  const std::vector<uint8_t> ground = segmentGround(points);
  const std::vector<uint8_t> road = extractRoadPoints(points, sweepRings(*log.sweep(sweepIndex)), ground);
  const SE3 cityTEgo = log.cityTEgo().at(log.sweepTimestamps()[sweepIndex]);
  size_t groundOnSurface = 0, trueGround = 0, trueGroundFound = 0, roadInside = 0, trueRoad = 0, trueRoadFound = 0;
  Proxies p;
  const RoadPointOptions roadOptions;
  const GroundSegmentationOptions groundOptions;
  for (size_t i = 0; i < points.size(); ++i) {
    const double range = points[i].head<2>().norm();
    const Eigen::Vector3d c = cityTEgo * points[i];
    const double h = map.groundHeight().bilinearAt(c.head<2>());
    const bool onSurface = std::isfinite(h) && std::abs(c.z() - h) < 0.15;
    const bool inside = map.drivable().contains(c.head<2>());
    p.ground += ground[i];
    p.road += road[i];
    groundOnSurface += ground[i] && onSurface;
    roadInside += road[i] && inside;
    if (range > groundOptions.minRange && range < roadOptions.maxRange && onSurface) {
      ++trueGround;
      trueGroundFound += ground[i];
      if (inside) {
        ++trueRoad;
        trueRoadFound += road[i];
      }
    }
  }
  p.groundPrecision = double(groundOnSurface) / double(p.ground);
  p.groundRecall = double(trueGroundFound) / double(trueGround);
  p.roadPrecision = double(roadInside) / double(p.road);
  p.roadRecall = double(trueRoadFound) / double(trueRoad);
  std::printf("sweep %zu: %zu points, %zu ground (precision %.3f, recall %.3f within %.0f m), %zu road (inside drivable "
              "%.3f, recall of ground-in-drivable %.3f)\n",
              sweepIndex, points.size(), p.ground, p.groundPrecision, p.groundRecall, roadOptions.maxRange, p.road,
              p.roadPrecision, p.roadRecall);
  return p;
}

TEST(RoadPointsReal, RoadPointsLieInsideTheDrivableArea) {
  const ArgoverseLog log(test::sharedLog());
  const HdMap map = HdMap::load(log.mapFiles(), {.boundaryDistance = false});
  for (size_t s = 0; s < log.sweepCount(); ++s) {
    const Proxies p = measure(log, map, s);
    EXPECT_GT(p.ground, 10000u);
    EXPECT_GT(p.groundPrecision, 0.90);
    EXPECT_GT(p.groundRecall, 0.85);
    EXPECT_GT(p.road, 5000u);
    EXPECT_GT(p.roadPrecision, 0.85);
    EXPECT_GT(p.roadRecall, 0.80);
  }
}

}  // namespace
}  // namespace hdprior
