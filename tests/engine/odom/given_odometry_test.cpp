#include <gtest/gtest.h>

#include <cmath>

#include "engine/error.h"
#include "engine/geom/angles.h"
#include "engine/odom/degraded_trajectory.h"
#include "engine/odom/given_odometry.h"
#include "engine/odom/odometry.h"
#include "error_message.h"

namespace hdprior {
namespace {

SE3 pose(const Eigen::Vector3d& axis, double angle, const Eigen::Vector3d& t) {
  return makeSE3(Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized())), t);
}

double angleBetween(const SE3& a, const SE3& b) { return Eigen::AngleAxisd(a.rotation().transpose() * b.rotation()).angle(); }

GivenOdometry given(std::vector<int64_t> stamps, std::vector<SE3> poses, GivenOdometryFrame frame = GivenOdometryFrame::First) {
  return {PoseTrajectory(std::move(stamps), std::move(poses), "given.tum"), frame, "given.tum", TrajectoryFormat::Tum};
}

using test::errorOf;

LidarSweep sweepAt(int64_t t) {
  LidarSweep s;
  s.timestampNs = t;
  s.points.push_back({1.0f, 2.0f, 0.5f, 10, 3, 1000});
  return s;
}

}  // namespace

// Halfway between two poses: half the rotation about the same axis (slerp), the mean translation;
// a quarter of the way: a quarter of the angle.
TEST(GivenOdometry, InterpolatesOnSE3BetweenTheFilesPoses) {
  const Eigen::Vector3d axis(0.2, -0.5, 1.0);
  const SE3 a = pose(axis, 0.1, {10, 20, 1}), b = pose(axis, 0.1 + 60 * kDegree, {14, 26, 3});
  const GivenOdometry g = given({1000, 3000}, {a, b}, GivenOdometryFrame::City);
  const PoseTrajectory at = givenOdometryAtSweeps(g, {1000, 1500, 2000, 3000}, SE3::Identity());
  const SE3 mid = at.poses()[2], quarter = at.poses()[1];
  EXPECT_LT((mid.translation() - Eigen::Vector3d(12, 23, 2)).norm(), 1e-12);
  EXPECT_NEAR(angleBetween(a, mid), 30 * kDegree, 1e-12);
  EXPECT_NEAR(angleBetween(mid, b), 30 * kDegree, 1e-12);
  EXPECT_LT((Eigen::AngleAxisd(a.rotation().transpose() * mid.rotation()).axis() - axis.normalized()).norm(), 1e-9);
  EXPECT_LT((quarter.translation() - Eigen::Vector3d(11, 21.5, 1.5)).norm(), 1e-12);
  EXPECT_NEAR(angleBetween(a, quarter), 15 * kDegree, 1e-12);
  EXPECT_TRUE(at.poses()[0].isApprox(a, 1e-12));
  EXPECT_TRUE(at.poses()[3].isApprox(b, 1e-12));
}

// `first`: the pose at the first sweep becomes the odometry origin (placed on the first ground-truth
// pose by the run); `city`: the file's poses are city_T_ego and come back through cityTOdom.
TEST(GivenOdometry, FirstFrameIsAnchoredAtTheFirstSweepCityFrameIsKept) {
  const std::vector<SE3> file = {pose({0, 0, 1}, 0.3, {100, -50, 2}), pose({0, 0, 1}, 0.5, {103, -48, 2.1}),
                                 pose({1, 0, 1}, 0.7, {107, -45, 2.3})};
  const SE3 cityTOdom = pose({0, 1, 1}, -1.2, {5000, 2300, 70});
  const std::vector<int64_t> sweeps = {150, 200, 300};
  const PoseTrajectory first = givenOdometryAtSweeps(given({100, 200, 300}, file), sweeps, cityTOdom);
  EXPECT_TRUE(first.poses()[0].isApprox(SE3::Identity(), 1e-12));
  const SE3 fileAtFirst = interpolate(file[0], file[1], 0.5);
  for (size_t i = 1; i < 3; ++i) {
    const SE3 expected = fileAtFirst.inverse() * file[i];  // relative motion since the first sweep kept
    EXPECT_TRUE(first.poses()[i].isApprox(expected, 1e-12)) << i;
  }
  const PoseTrajectory city = givenOdometryAtSweeps(given({100, 200, 300}, file, GivenOdometryFrame::City), sweeps, cityTOdom);
  EXPECT_LT(((cityTOdom * city.poses()[2]).translation() - file[2].translation()).norm(), 1e-9);
  EXPECT_LT(angleBetween(cityTOdom * city.poses()[2], file[2]), 1e-12);
}

TEST(GivenOdometry, SweepsMustBeCoveredWithinOneMillisecond) {
  const GivenOdometry g = given({10'000'000, 20'000'000}, {SE3::Identity(), pose({0, 0, 1}, 0.1, {1, 0, 0})});
  // 0.5 ms outside either end: the end pose.
  const PoseTrajectory near = givenOdometryAtSweeps(g, {9'500'000, 20'500'000}, SE3::Identity());
  EXPECT_TRUE(near.poses()[1].isApprox(g.trajectory.poses()[1], 1e-12));
  EXPECT_NE(errorOf([&] { givenOdometryAtSweeps(g, {8'000'000, 15'000'000}, SE3::Identity()); })
                .find("given.tum: the poses span 0.010000000 to 0.020000000 s but sweep 0 is at 0.008000000 s, 2.000 ms before the first pose"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { givenOdometryAtSweeps(g, {15'000'000, 21'500'000}, SE3::Identity()); })
                .find("sweep 1 is at 0.021500000 s, 1.500 ms after the last pose"),
            std::string::npos);
  EXPECT_EQ(parseGivenOdometryFrame("city", "o"), GivenOdometryFrame::City);
  EXPECT_NE(errorOf([] { parseGivenOdometryFrame("map", "option --odometry-frame"); })
                .find("option --odometry-frame: must be first or city, not 'map'"),
            std::string::npos);
}

// The odometry with given poses registers nothing: its frames are the given poses, without
// covariance, and keyframes come from them by distance and angle as always.
TEST(GivenOdometry, OdometryTakesTheGivenPosesAndMakesKeyframesFromThem) {
  std::vector<int64_t> stamps;
  std::vector<SE3> poses;
  for (int i = 0; i < 12; ++i) {
    stamps.push_back(1000 + 100 * i);
    poses.push_back(pose({0, 0, 1}, 0.01 * i, {0.7 * i, 0.02 * i, 0}));
  }
  KeyframeOptions keyframes;
  keyframes.distance = 2.0;
  Odometry odometry({}, keyframes, PoseTrajectory(stamps, poses, "given"));
  EXPECT_TRUE(odometry.givenPoses());
  for (int64_t t : stamps) odometry.registerSweep(sweepAt(t));
  ASSERT_EQ(odometry.frames().size(), 12u);
  for (size_t i = 0; i < 12; ++i) {
    EXPECT_TRUE(odometry.frames()[i].odomTEgo.isApprox(poses[i], 1e-12)) << i;
    EXPECT_TRUE(odometry.frames()[i].covariance.isZero());
  }
  EXPECT_EQ(odometry.localMapPoints(), 0u);
  std::vector<size_t> keyframeFrames;
  for (const Keyframe& k : odometry.keyframes()) keyframeFrames.push_back(k.frame);
  EXPECT_EQ(keyframeFrames, (std::vector<size_t>{0, 3, 6, 9}));  // every 2.1 m
  EXPECT_TRUE(odometry.keyframes()[2].previousTThis.isApprox(poses[3].inverse() * poses[6], 1e-12));
  // A sweep the given trajectory does not have is an error, not a guess.
  Odometry short_({}, keyframes, PoseTrajectory({1000, 1100}, {poses[0], poses[1]}, "given"));
  short_.registerSweep(sweepAt(1000));
  EXPECT_THROW(short_.registerSweep(sweepAt(1200)), Error);
}

// Drift on top of given poses degrades them as it does the lidar odometry's.
TEST(GivenOdometry, InjectedDriftDegradesTheGivenPoses) {
  std::vector<int64_t> stamps;
  std::vector<SE3> poses;
  for (int i = 0; i < 5; ++i) {
    stamps.push_back(100 * i);
    poses.push_back(pose({0, 0, 1}, 0.02 * i, {1.0 * i, 0, 0}));
  }
  OdometryOptions options;
  options.drift = {0.01, 1.0, 0.0};
  Odometry odometry(options, {}, PoseTrajectory(stamps, poses, "given"));
  for (int64_t t : stamps) odometry.registerSweep(sweepAt(t));
  const std::vector<SE3> expected = driftedPoses(poses, options.drift);
  for (size_t i = 0; i < poses.size(); ++i) EXPECT_TRUE(odometry.frames()[i].odomTEgo.isApprox(expected[i], 1e-12)) << i;
}

TEST(DegradedTrajectory, DriftAsOdometryDriftPlusASeededRandomWalk) {
  std::vector<SE3> straight{SE3::Identity()};
  for (int i = 0; i < 200; ++i) straight.push_back(straight.back() * pose({0, 0, 1}, 0.0, {0.5, 0, 0}));
  const OdometryDrift drift{0.007, 0.5, 0.2};
  // Without a random walk: exactly the drift model's poses.
  const std::vector<SE3> drifted = degradedPoses(straight, drift, {});
  const std::vector<SE3> reference = driftedPoses(straight, drift);
  for (size_t i = 0; i < straight.size(); ++i) EXPECT_TRUE(drifted[i].isApprox(reference[i], 1e-12)) << i;
  EXPECT_NEAR(drifted.back().translation().norm(), 100.7, 0.05);

  const RandomWalk walk{0.01, 0.01, 7};
  const std::vector<SE3> a = degradedPoses(straight, drift, walk), b = degradedPoses(straight, drift, walk);
  const std::vector<SE3> other = degradedPoses(straight, drift, {0.01, 0.01, 8});
  for (size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(a[i].isApprox(b[i], 0.0)) << i;  // same seed, same poses
  EXPECT_GT((a.back().translation() - other.back().translation()).norm(), 1e-3);
  EXPECT_TRUE(a.front().isApprox(straight.front(), 0.0));
  // The walk's spread: per axis sigma * sqrt(100 m) = 0.1 m of translation noise alone, plus the
  // heading noise integrated along the way; it neither vanishes nor dominates the 0.7 m scale error.
  const double off = (a.back().translation() - drifted.back().translation()).norm();
  EXPECT_GT(off, 0.01);
  EXPECT_LT(off, 2.0);

  EXPECT_EQ(parseRandomWalk("0.002,0.003", "o").rotationSigmaDeg, 0.003);
  EXPECT_NE(errorOf([] { parseRandomWalk("0.002", "option --random-walk"); }).find("option --random-walk: '0.002' is not SIGMA_M,SIGMA_DEG"),
            std::string::npos);
  EXPECT_NE(errorOf([] { parseRandomWalk("2,0", "option --random-walk"); }).find("each sigma must be in [0, 1]"), std::string::npos);
}

}  // namespace hdprior
