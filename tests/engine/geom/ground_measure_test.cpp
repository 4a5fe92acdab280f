#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/geom/ground_measure.h"
#include "engine/geom/se2.h"

namespace hdprior {
namespace {

// A pair constructed 3 m along and 2 m to the right of a heading of 30 degrees: the components come
// back exactly, the distance is their hypotenuse, the rise the height difference.
TEST(GroundMeasure, SplitsTheDistanceAlongAndAcrossTheHeading) {
  const double heading = 30.0 * std::numbers::pi / 180.0;
  const Eigen::Vector3d from(12.0, -4.0, 1.5);
  const Eigen::Vector3d to2 = offsetPose({from.x(), from.y(), heading}, {3.0, -2.0, 0.0});
  const GroundMeasure m = measureGround(from, {to2.x(), to2.y(), 1.8}, heading);
  EXPECT_NEAR(m.along, 3.0, 1e-9);
  EXPECT_NEAR(m.lateral, -2.0, 1e-9);
  EXPECT_NEAR(m.distance, std::sqrt(13.0), 1e-9);
  EXPECT_NEAR(m.rise, 0.3, 1e-9);
  // Seen along the opposite heading the components change sign, the distance does not.
  const GroundMeasure back = measureGround(from, {to2.x(), to2.y(), 1.8}, heading + std::numbers::pi);
  EXPECT_NEAR(back.along, -3.0, 1e-9);
  EXPECT_NEAR(back.lateral, 2.0, 1e-9);
  EXPECT_NEAR(back.distance, m.distance, 1e-12);
}

}  // namespace
}  // namespace hdprior
