// Picking on the real log: the nearest sweep point with its label, range and height, the drivable
// polygon under a place (agreeing with the drivable raster), and the NDT cell there.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/point_labels.h"
#include "engine/pipeline/point_pick.h"
#include "test_data.h"

namespace hdprior {
namespace {

struct RealFrame {
  ArgoverseLog log{test::sharedLog()};
  HdMap map = HdMap::load(log.mapFiles(), HdMapOptions{.ndtCellSizes = {1.0}});
  SE3 pose = log.cityTEgoAtSweeps().poses().front();
  std::shared_ptr<const LidarSweep> sweep = log.sweep(0);
  std::vector<SubmapLabel> labels = sweepPointLabels(*sweep, pose, defaultConfig().roadPoints);
};

const RealFrame& real() {
  static const RealFrame r;
  return r;
}

TEST(PointPick, NamesTheSweepPointAtAPlace) {
  const RealFrame& r = real();
  ASSERT_EQ(r.labels.size(), r.sweep->points.size());
  size_t counts[4] = {};
  for (SubmapLabel l : r.labels) ++counts[int(l)];
  EXPECT_GT(counts[int(SubmapLabel::Road)], 1000u);
  EXPECT_GT(counts[int(SubmapLabel::Other)], 10000u);
  for (size_t i : {size_t(17), r.sweep->points.size() / 2, r.sweep->points.size() - 5}) {
    const LidarPoint& p = r.sweep->points[i];
    const Eigen::Vector3d city = r.pose * Eigen::Vector3d(p.x, p.y, p.z);
    const Pick pick = pickAt(city.head<2>(), *r.sweep, r.labels, r.pose, r.map);
    ASSERT_TRUE(pick.point.has_value());
    // Another point may lie at the same place in the plane (above or below it): the same distance.
    EXPECT_LT(pick.point->distance, 1e-6);
    const LidarPoint& q = r.sweep->points[pick.point->index];
    EXPECT_NEAR(std::hypot(q.x - p.x, q.y - p.y), 0.0, 1e-3);
    EXPECT_EQ(pick.point->label, r.labels[pick.point->index]);
    EXPECT_NEAR(pick.point->range, std::sqrt(double(q.x) * q.x + double(q.y) * q.y + double(q.z) * q.z), 1e-9);
    const double ground = r.map.groundHeight().bilinearAt(pick.point->city.head<2>());
    if (std::isfinite(ground)) EXPECT_NEAR(pick.point->heightAboveGround, pick.point->city.z() - ground, 1e-9);
  }
  // Far from every point: none.
  EXPECT_FALSE(pickAt(r.pose.translation().head<2>() + Eigen::Vector2d(500, 500), *r.sweep, r.labels, r.pose, r.map).point);
}

TEST(PointPick, TheDrivablePolygonAgreesWithTheRasterAndTheCellWithTheGrid) {
  const RealFrame& r = real();
  const Eigen::Vector2d centre = r.pose.translation().head<2>();
  size_t agree = 0, total = 0, drivable = 0;
  for (double dx = -40; dx <= 40; dx += 1.37)
    for (double dy = -40; dy <= 40; dy += 1.37) {
      const Eigen::Vector2d at = centre + Eigen::Vector2d(dx, dy);
      const Pick pick = pickAt(at, *r.sweep, r.labels, r.pose, r.map, {.radius = 0.5, .ndtCellSize = 1.0});
      agree += pick.drivableArea.has_value() == r.map.drivable().contains(at);
      drivable += pick.drivableArea.has_value();
      ++total;
      const NdtCell* cell = r.map.ndtGrid(1.0).cellAt(at);
      ASSERT_EQ(pick.cell.has_value(), cell != nullptr);
      if (cell) EXPECT_EQ(pick.cell->mean, cell->mean);
    }
  EXPECT_GT(drivable, total / 10);
  // The raster is 0.1 m: only places within a cell of a polygon edge may disagree.
  EXPECT_GT(double(agree) / double(total), 0.98) << agree << " of " << total;
  const std::string text = pickText(pickAt(centre, *r.sweep, r.labels, r.pose, r.map, {.radius = 2.0, .ndtCellSize = 1.0}));
  EXPECT_EQ(text.rfind("pick: ", 0), 0u) << text;
  EXPECT_NE(text.find("drivable area "), std::string::npos) << text;  // the ego stands on the road
}

}  // namespace
}  // namespace hdprior
