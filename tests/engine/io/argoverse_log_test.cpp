#include "engine/io/argoverse_log.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/error.h"
#include "test_data.h"

namespace hdprior {
namespace {

TEST(ArgoverseLog, OpensRealLog) {
  const ArgoverseLog log(test::sharedLog());
  EXPECT_EQ(log.id(), "7fab2350-7eaf-3b7e-a39d-6937a4c1bede");
  EXPECT_EQ(log.city(), "PIT");
  ASSERT_EQ(log.sweepCount(), 2u);
  EXPECT_EQ(log.sweepTimestamps()[0], 315966265259836000);
  EXPECT_EQ(log.sweepTimestamps()[1], 315966265360032000);
  EXPECT_EQ(log.cityTEgo().size(), 2706u);
  EXPECT_EQ(log.cityTEgo().startNs(), 315966253572412942);
  EXPECT_EQ(log.cityTEgo().endNs(), 315966269522412935);
  EXPECT_DOUBLE_EQ(log.cityTEgo().poses()[0].translation().x(), 5172.668216028519);
  EXPECT_TRUE(log.calibration().count("up_lidar"));
  EXPECT_TRUE(log.calibration().count("down_lidar"));
}

TEST(ArgoverseLog, LoadsSweepsLazilyWithKnownValues) {
  const ArgoverseLog log(test::sharedLog(), 1);
  const auto sweep = log.sweep(0);
  ASSERT_EQ(sweep->points.size(), 99229u);
  EXPECT_EQ(sweep->timestampNs, 315966265259836000);
  const LidarPoint& first = sweep->points.front();
  EXPECT_EQ(first.x, -1.537109375f);
  EXPECT_EQ(first.y, 3.060546875f);
  EXPECT_EQ(first.z, -0.322509765625f);
  EXPECT_EQ(first.intensity, 10);
  EXPECT_EQ(first.laserNumber, 31);
  EXPECT_EQ(first.offsetNs, 2654000);
  EXPECT_EQ(sweep->points.back().offsetNs, 106085816);
  EXPECT_EQ(log.sweep(1)->points.size(), 99466u);
  EXPECT_EQ(log.sweep(0).get() == sweep.get(), false);  // cache of one: reloaded
  EXPECT_THROW(log.sweep(2), Error);
}

TEST(ArgoverseLog, DownLidarIsMountedUpsideDown) {
  const ArgoverseLog log(test::sharedLog());
  const Eigen::Vector3d upZ = log.calibration().at("up_lidar").rotation().col(2);
  const Eigen::Vector3d downZ = log.calibration().at("down_lidar").rotation().col(2);
  EXPECT_GT(upZ.z(), 0.9);
  EXPECT_LT(downZ.z(), -0.9);
}

TEST(PoseTrajectory, InterpolatesInsideSpanAndRejectsOutside) {
  const ArgoverseLog log(test::sharedLog());
  const PoseTrajectory& T = log.cityTEgo();
  const int64_t t0 = T.timestamps()[10], t1 = T.timestamps()[11];
  EXPECT_TRUE(T.at(t0).isApprox(T.poses()[10]));
  const SE3 mid = T.at((t0 + t1) / 2);
  const Eigen::Vector3d expected = 0.5 * (T.poses()[10].translation() + T.poses()[11].translation());
  EXPECT_NEAR((mid.translation() - expected).norm(), 0.0, 1e-3);
  EXPECT_NEAR(Eigen::Quaterniond(mid.rotation()).norm(), 1.0, 1e-12);
  EXPECT_NO_THROW(T.at(log.sweepTimestamps()[0]));
  try {
    T.at(T.endNs() + 1);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(e.reason().find("outside the pose time span"), std::string::npos);
  }
  EXPECT_THROW(PoseTrajectory({2, 1}, {SE3::Identity(), SE3::Identity()}), Error);
}

TEST(ArgoverseLog, MissingDirectoryIsAnError) {
  EXPECT_THROW(ArgoverseLog("/nonexistent/log"), Error);
}

}  // namespace
}  // namespace hdprior
