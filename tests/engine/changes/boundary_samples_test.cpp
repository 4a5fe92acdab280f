// Samples along a polygon's boundary, their normals and the stretches between arc lengths.
#include "engine/changes/boundary_samples.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "engine/map/synthetic_maps.h"

namespace hdprior {
namespace {

TEST(BoundarySamples, NormalsPointOutwardsWhicheverWayTheVerticesTurn) {
  for (bool clockwise : {false, true}) {
    Polyline3 square = test::rectangle(0, 0, 10, 10);
    if (clockwise) std::reverse(square.begin(), square.end());
    const std::vector<BoundarySample> samples = sampleBoundary(square, 1.0);
    ASSERT_EQ(samples.size(), 40u);
    for (const BoundarySample& s : samples) {
      const Eigen::Vector2d outside = s.point + 0.1 * s.normal;
      EXPECT_TRUE(outside.x() < 0 || outside.x() > 10 || outside.y() < 0 || outside.y() > 10) << clockwise;
    }
    EXPECT_DOUBLE_EQ(perimeter(square), 40.0);
  }
  const std::vector<Eigen::Vector2d> part = boundaryBetween(test::rectangle(0, 0, 10, 10), 5, 15);
  ASSERT_EQ(part.size(), 3u);
  EXPECT_TRUE(part[0].isApprox(Eigen::Vector2d(5, 0)));
  EXPECT_TRUE(part[1].isApprox(Eigen::Vector2d(10, 0)));
  EXPECT_TRUE(part[2].isApprox(Eigen::Vector2d(10, 5)));
}

}  // namespace
}  // namespace hdprior
