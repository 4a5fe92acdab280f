// Drives for the simulator: a lane route at a speed profile, and a real log's own poses.
#include "engine/sim/trajectory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/vector_map.h"
#include "engine/sim/town_generator.h"
#include "test_data.h"

namespace hdprior {
namespace {

// A procedural town's ground height and lane graph, as the simulator drives them.
struct Town {
  explicit Town(uint64_t seed)
      : map(generateTown(TownOptions{}, seed)),
        ground(GroundHeight::fromNpy(map.groundHeight, map.imgSim2City, "town")),
        lanes(map.vectorMap, {}, "town") {}
  TownMap map;
  GroundHeight ground;
  LaneGraph lanes;
};

TEST(RouteTrajectory, CruisesSlowsStopsAndStaysOnTheGround) {
  const Town town(7);
  const GroundHeight& ground = town.ground;
  const LaneGraph& lanes = town.lanes;
  RouteOptions o;
  o.seconds = 60.0;
  o.stopProbability = 1.0;
  const PoseTrajectory T = routeTrajectory(lanes, ground, o, 3);
  EXPECT_NEAR(double(T.endNs() - T.startNs()) * 1e-9, 60.15, 0.01);
  EXPECT_EQ(T.size(), size_t(60.15 * 200) + 1);  // 200 Hz
  double maxSpeed = 0.0, distance = 0.0, stoppedSeconds = 0.0, maxTilt = 0.0;
  for (size_t i = 1; i < T.size(); ++i) {
    const double d = (T.poses()[i].translation() - T.poses()[i - 1].translation()).head<2>().norm();
    const double v = d / 0.005;
    maxSpeed = std::max(maxSpeed, v);
    distance += d;
    if (v < 0.01) stoppedSeconds += 0.005;
    const Eigen::Vector3d up = T.poses()[i].linear().col(2);
    maxTilt = std::max(maxTilt, std::acos(std::clamp(up.z(), -1.0, 1.0)));
    // z from the ground height plus the ego origin's height.
    const Eigen::Vector3d p = T.poses()[i].translation();
    ASSERT_NEAR(p.z(), ground.bilinearAt(p.head<2>()) + 0.32, 1e-9);
  }
  EXPECT_LE(maxSpeed, 8.0 + 1e-6);
  EXPECT_GT(distance, 250.0);          // cruising most of the time
  EXPECT_LT(distance, 8.0 * 60.0);     // but slower in turns and at stops
  EXPECT_GE(stoppedSeconds, 1.9);      // at least one 2 s stop at a junction
  EXPECT_GT(maxTilt, 0.01);            // roll/pitch follow the hills (up to 8 %)
  EXPECT_LT(maxTilt, 0.1);
  std::printf("[ info ] 60 s route: %.0f m, stopped %.1f s, max tilt %.3f rad\n", distance, stoppedSeconds, maxTilt);
  // Deterministic by seed.
  const PoseTrajectory again = routeTrajectory(lanes, ground, o, 3);
  EXPECT_TRUE(again.poses().back().isApprox(T.poses().back(), 0.0));
}

// Lane centerlines are polylines; the car's heading must still turn smoothly through a junction
// (it used to jump 6-7 degrees at each connector vertex, which no odometry's motion model expects).
TEST(RouteTrajectory, TurnsSmoothlyWithTheHeadingAlongTheMotion) {
  const Town town(4);
  RouteOptions o;
  o.seconds = 60.0;
  const PoseTrajectory T = routeTrajectory(town.lanes, town.ground, o, 4);
  const auto yawAt = [&](size_t i) { return std::atan2(T.poses()[i].linear()(1, 0), T.poses()[i].linear()(0, 0)); };
  double turned = 0.0, maxRateChange = 0.0, maxSlip = 0.0, previousRate = 0.0;
  for (size_t i = 20; i < T.size(); i += 20) {  // 10 Hz, a sweep's period
    const double rate = std::remainder(yawAt(i) - yawAt(i - 20), 2 * std::numbers::pi);
    turned += std::abs(rate);
    if (i > 20) maxRateChange = std::max(maxRateChange, std::abs(rate - previousRate));
    previousRate = rate;
    const Eigen::Vector2d motion = (T.poses()[i].translation() - T.poses()[i - 20].translation()).head<2>();
    if (motion.norm() > 0.1) {
      const double heading = yawAt(i - 10);
      const double slip = std::abs(std::remainder(std::atan2(motion.y(), motion.x()) - heading, 2 * std::numbers::pi));
      maxSlip = std::max(maxSlip, slip);
    }
  }
  const double deg = 180.0 / std::numbers::pi;
  std::printf("[ info ] turned %.0f deg, heading rate change per sweep <= %.2f deg, slip <= %.2f deg\n", turned * deg,
              maxRateChange * deg, maxSlip * deg);
  EXPECT_GT(turned * deg, 80.0);          // this route turns at a junction
  EXPECT_LT(maxRateChange * deg, 1.5);    // was 7 degrees with the polyline's kinks
  EXPECT_LT(maxSlip * deg, 4.0);          // heading against the chord of a sweep's motion (2.9 where a connector meets its lane)
}

TEST(RouteTrajectory, RejectsBadOptions) {
  const Town town(7);
  RouteOptions o;
  o.seconds = -1;
  EXPECT_THROW(routeTrajectory(town.lanes, town.ground, o, 1), Error);
  o.seconds = 1;
  o.poseRateHz = 50;
  EXPECT_THROW(routeTrajectory(town.lanes, town.ground, o, 1), Error);
}

TEST(CropTrajectory, KeepsTheRealPosesForTheAskedSpan) {
  const ArgoverseLog log(test::sharedLog());
  const PoseTrajectory T = cropTrajectory(log.cityTEgo(), 2.0);
  EXPECT_EQ(T.startNs(), log.cityTEgo().startNs());
  EXPECT_EQ(T.endNs(), log.cityTEgo().startNs() + 2'150'000'000);
  for (size_t i = 0; i + 1 < T.size(); ++i) EXPECT_TRUE(T.poses()[i].isApprox(log.cityTEgo().poses()[i], 0.0));
  EXPECT_THROW(cropTrajectory(log.cityTEgo(), 100.0), Error);
}

}  // namespace
}  // namespace hdprior
