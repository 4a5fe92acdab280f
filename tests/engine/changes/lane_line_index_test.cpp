// The lane boundaries' index: painted or not, how near, and which way they run.
#include "engine/changes/lane_line_index.h"

#include <gtest/gtest.h>

namespace hdprior {
namespace {

// A lane along x from 0 to 40 m: its left boundary (y 2) painted, its right one (y -2) not, and
// a painted boundary far away that must not be found.
VectorMap oneLane() {
  VectorMap map;
  LaneSegment lane;
  lane.leftLaneBoundary = {{0, 2, 0}, {20, 2, 0}, {40, 2, 0}};
  lane.leftLaneMarkType = "SOLID_WHITE";
  lane.rightLaneBoundary = {{0, -2, 0}, {40, -2, 0}};
  lane.rightLaneMarkType = "NONE";
  LaneSegment far;
  far.leftLaneBoundary = {{500, 0, 0}, {500, 40, 0}};
  far.leftLaneMarkType = "DASHED_WHITE";
  map.laneSegments = {lane, far};
  return map;
}

TEST(LaneLineIndex, APointIsNearAPaintedLineWithinTheReachOnly) {
  const LaneLineIndex index(oneLane());
  EXPECT_TRUE(index.nearPainted({25, 2.9}, 1.0));
  EXPECT_FALSE(index.nearPainted({25, 3.1}, 1.0));
  EXPECT_FALSE(index.nearPainted({25, -2.0}, 1.0)) << "the right boundary is not painted";
  EXPECT_FALSE(index.nearPainted({41.5, 2.0}, 1.0)) << "beyond the line's end";
  EXPECT_TRUE(index.nearPainted({500.5, 20}, 1.0));
}

TEST(LaneLineIndex, TheDirectionIsTheNearestBoundarysPaintedOrNot) {
  const LaneLineIndex index(oneLane());
  const std::optional<Eigen::Vector2d> d = index.directionAt({10, -1.5}, 15.0);
  ASSERT_TRUE(d.has_value());
  EXPECT_NEAR(d->x(), 1.0, 1e-9);
  EXPECT_NEAR(d->y(), 0.0, 1e-9);
  const std::optional<Eigen::Vector2d> far = index.directionAt({499, 10}, 15.0);
  ASSERT_TRUE(far.has_value());
  EXPECT_NEAR(std::abs(far->y()), 1.0, 1e-9);
  EXPECT_FALSE(index.directionAt({200, 100}, 15.0).has_value());
}

}  // namespace
}  // namespace hdprior
