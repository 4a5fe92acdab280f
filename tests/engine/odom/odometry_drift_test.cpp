#include <gtest/gtest.h>

#include <cmath>

#include "engine/error.h"
#include "engine/eval/trajectory_errors.h"
#include "engine/geom/angles.h"
#include "engine/io/argoverse_log.h"
#include "engine/odom/odometry.h"
#include "engine/odom/odometry_drift.h"
#include "engine/sim/log_writer.h"
#include "error_message.h"
#include "test_data.h"

namespace hdprior {
namespace {

// The message parsing `text` as --odometry-drift fails with, or "" when it is accepted.
std::string driftErrorOf(const std::string& text) { return test::errorOf([&] { parseOdometryDrift(text, "option --odometry-drift"); }); }

SE3 planar(double x, double y, double yaw) {
  SE3 T = SE3::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, 0.0);
  return T;
}

// n steps of `step` from the identity.
std::vector<SE3> repeated(const SE3& step, int n) {
  std::vector<SE3> poses{SE3::Identity()};
  for (int i = 0; i < n; ++i) poses.push_back(poses.back() * step);
  return poses;
}

// sum_{i < n} Rz(i beta) v = sin(n beta / 2) / sin(beta / 2) Rz((n - 1) beta / 2) v.
Eigen::Vector3d rotatedSum(const Eigen::Vector3d& v, double beta, int n) {
  if (beta == 0.0) return double(n) * v;
  return std::sin(n * beta / 2) / std::sin(beta / 2) * (Eigen::AngleAxisd((n - 1) * beta / 2, Eigen::Vector3d::UnitZ()) * v);
}

}  // namespace

TEST(OdometryDrift, ParsesScaleYawAndOptionalPitch) {
  OdometryDrift d = parseOdometryDrift("0.007,0.5", "x");
  EXPECT_DOUBLE_EQ(d.scale, 0.007);
  EXPECT_DOUBLE_EQ(d.yawDegPer100m, 0.5);
  EXPECT_DOUBLE_EQ(d.pitchDegPer100m, 0.0);
  EXPECT_TRUE(d.active());
  d = parseOdometryDrift("-0.01,-2,0.25", "x");
  EXPECT_DOUBLE_EQ(d.scale, -0.01);
  EXPECT_DOUBLE_EQ(d.yawDegPer100m, -2.0);
  EXPECT_DOUBLE_EQ(d.pitchDegPer100m, 0.25);
  EXPECT_FALSE(parseOdometryDrift("0,0", "x").active());
  EXPECT_NO_THROW(parseOdometryDrift("0.1999,20,-20", "x"));
}

TEST(OdometryDrift, BadValuesAreOneLineErrorsNamingTheOption) {
  EXPECT_EQ(driftErrorOf("0.2,0"), "option --odometry-drift: scale = 0.2 is out of range (-0.2, 0.2)");
  EXPECT_EQ(driftErrorOf("-0.25,0"), "option --odometry-drift: scale = -0.25 is out of range (-0.2, 0.2)");
  EXPECT_EQ(driftErrorOf("0.007,20.5"), "option --odometry-drift: yaw_deg_per_100m = 20.5 is out of range [-20, 20]");
  EXPECT_EQ(driftErrorOf("0.007,0.5,-21"), "option --odometry-drift: pitch_deg_per_100m = -21 is out of range [-20, 20]");
  for (const char* bad : {"", "0.007", "0.007,0.5,0,1", "0.007,,0.5"}) {
    EXPECT_EQ(driftErrorOf(bad).rfind("option --odometry-drift: ", 0), 0u) << bad;
    EXPECT_NE(driftErrorOf(bad).find("SCALE,YAW_DEG_PER_100M"), std::string::npos) << bad;
  }
  for (const char* bad : {"abc,0.5", "0.007,0.5x", "nan,0", "0.007,inf", "1e400,0"}) {
    EXPECT_NE(driftErrorOf(bad).find("is not a number"), std::string::npos) << bad << ": " << driftErrorOf(bad);
  }
  for (const char* bad : {"", "abc,0.5", "0.3,0"}) EXPECT_EQ(driftErrorOf(bad).find('\n'), std::string::npos) << bad;
  EXPECT_EQ(odometryDriftProblem({}), "");
  EXPECT_NE(odometryDriftProblem({std::nan(""), 0, 0}), "");
}

TEST(OdometryDrift, ZeroDriftKeepsEveryPoseBitForBit) {
  const std::vector<SE3> poses = repeated(planar(0.8, 0.01, 0.003), 50);
  const std::vector<SE3> same = driftedPoses(poses, {});
  ASSERT_EQ(same.size(), poses.size());
  for (size_t i = 0; i < poses.size(); ++i) EXPECT_TRUE(same[i].matrix() == poses[i].matrix()) << i;
}

// A straight drive of 250 steps of 0.8 m along x: the scale lengthens it by exactly 0.7 %; the yaw
// drift turns every step by k |t| more, so the end is a sum of rotated steps (closed form).
TEST(OdometryDrift, StraightTrajectoryEndPointIsAnalytic) {
  const int n = 250;
  const double step = 0.8, length = n * step;
  const std::vector<SE3> truth = repeated(planar(step, 0, 0), n);

  const std::vector<SE3> scaled = driftedPoses(truth, {0.007, 0.0, 0.0});
  EXPECT_NEAR((scaled.back().translation() - Eigen::Vector3d(1.007 * length, 0, 0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(scaled.back().translation().x() - length, 1.4, 1e-9);  // 0.7 % of 200 m

  const OdometryDrift drift{0.007, 0.5, 0.0};
  const std::vector<SE3> drifted = driftedPoses(truth, drift);
  const double beta = 0.5 / 100.0 * step * kDegree;  // per step
  const Eigen::Vector3d expected = 1.007 * rotatedSum({step, 0, 0}, beta, n);
  EXPECT_NEAR((drifted.back().translation() - expected).norm(), 0.0, 1e-9);
  EXPECT_NEAR(Eigen::AngleAxisd(drifted.back().rotation()).angle(), n * beta, 1e-12);  // 1 deg over 200 m
  // Small-angle check of the closed form: lateral = k L^2 / 2 (1.007 for the scale).
  EXPECT_NEAR(drifted.back().translation().y(), 1.007 * 0.5 / 100.0 * kDegree * length * (length - step) / 2.0, 1e-4);

  // Pitch tips the nose down: the drive descends by the same sum about y.
  const std::vector<SE3> pitched = driftedPoses(truth, {0.0, 0.0, 2.0});
  const double b = 2.0 / 100.0 * step * kDegree;
  EXPECT_NEAR(pitched.back().translation().z(), -std::sin(n * b / 2) / std::sin(b / 2) * step * std::sin((n - 1) * b / 2), 1e-9);
  EXPECT_NEAR(pitched.back().translation().x(), std::sin(n * b / 2) / std::sin(b / 2) * step * std::cos((n - 1) * b / 2), 1e-9);
}

// A circle of radius 30 m in 0.6 m chords turning left: with the drift every chord is 0.7 % longer
// and turns by phi + k |t|, so the drifted drive is again a regular polygon.
TEST(OdometryDrift, CurvedTrajectoryEndPointIsAnalytic) {
  const double radius = 30.0, phi = 0.02;
  const int n = 200;  // 4 rad of arc, 120 m
  const Eigen::Vector3d chord(radius * std::sin(phi), radius * (1 - std::cos(phi)), 0.0);
  const std::vector<SE3> truth = repeated(planar(chord.x(), chord.y(), phi), n);
  for (const OdometryDrift& d : {OdometryDrift{0.007, 0.5, 0.0}, OdometryDrift{-0.01, -3.0, 0.0}}) {
    const std::vector<SE3> drifted = driftedPoses(truth, d);
    const double beta = phi + d.yawDegPer100m / 100.0 * chord.norm() * kDegree;
    const Eigen::Vector3d expected = (1.0 + d.scale) * rotatedSum(chord, beta, n);
    EXPECT_NEAR((drifted.back().translation() - expected).norm(), 0.0, 1e-9) << d.scale;
    const Eigen::Matrix3d heading = Eigen::AngleAxisd(n * beta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    EXPECT_LT((drifted.back().rotation() - heading).norm(), 1e-9);
    // The truth itself closes the same way without drift.
    EXPECT_NEAR((truth.back().translation() - rotatedSum(chord, phi, n)).norm(), 0.0, 1e-9);
  }
}

// What `hdprior run --odometry-drift S,Y` should report against ground truth on a straight drive:
// over a 100 m segment the scale is 100 |S| % along the road and the yaw drift k = Y deg/100 m puts
// the segment's end k L / 2 (0.436 % of L for Y = 0.5) to the side, so the RPE translation is their
// hypotenuse (0.825 % for 0.007,0.5); the yaw drift is Y deg/100 m.
TEST(OdometryDrift, RelativePoseErrorOfAStraightDriveShowsTheDrift) {
  const int n = 600;  // 0.5 m steps: segments of exactly 100 m (sums of 0.5 are exact)
  const std::vector<SE3> truth = repeated(planar(0.5, 0, 0), n);
  std::vector<int64_t> stamps;
  for (int i = 0; i <= n; ++i) stamps.push_back(int64_t(i) * 100'000'000);
  const PoseTrajectory gt(stamps, truth, "truth");
  auto evaluate = [&](const OdometryDrift& d) {
    return evaluateTrajectory(gt, PoseTrajectory(stamps, driftedPoses(truth, d), "drifted"), AlignmentMode::None);
  };
  const TrajectoryEvaluation scaleOnly = evaluate({0.007, 0.0, 0.0});
  ASSERT_GT(scaleOnly.rpe100.segments, 0u);
  EXPECT_NEAR(scaleOnly.rpe100.translationPercent, 0.7, 1e-6);
  EXPECT_NEAR(scaleOnly.rpe100.yawDegPer100m, 0.0, 1e-9);

  const TrajectoryEvaluation e = evaluate({0.007, 0.5, 0.0});
  const double lateralPercent = 0.5 / 100.0 * kDegree * 100.0 / 2.0 * 100.0;  // k L / 2 over L = 100 m, in %
  EXPECT_NEAR(lateralPercent, 0.436, 1e-3);
  EXPECT_NEAR(e.rpe100.translationPercent, std::hypot(0.7, lateralPercent), 0.005);
  EXPECT_NEAR(e.rpe100.yawDegPer100m, 0.5, 1e-6);
  EXPECT_NEAR(e.rpe10.translationPercent, std::hypot(0.7, lateralPercent / 10.0), 0.005);
}

// The Odometry reports drifted poses while registering on its own estimate: its frames are the
// undrifted run's frames degraded step by step, with the same scan-to-map covariances (the local map
// and predictions saw no drift), and its keyframes' relative poses come from the drifted frames.
TEST(OdometryDrift, OdometryReportsTheDriftButRegistersOnItsOwnEstimate) {
  SimulationOptions sim;
  sim.townSeed = 3;
  sim.seed = 2;
  sim.seconds = 3.0;
  sim.outDir = test::freshOutputDir("odometry_drift_sim");
  const ArgoverseLog log(simulateLog(sim).dir);
  OdometryOptions drifted;
  drifted.drift = {0.01, 2.0, -1.0};
  Odometry plain{OdometryOptions{}}, degraded{drifted};
  for (size_t i = 0; i < log.sweepCount(); ++i) {
    const auto sweep = log.sweep(i);
    plain.registerSweep(*sweep);
    degraded.registerSweep(*sweep);
  }
  std::vector<SE3> plainPoses;
  for (const OdometryFrame& f : plain.frames()) plainPoses.push_back(f.odomTEgo);
  const std::vector<SE3> expected = driftedPoses(plainPoses, drifted.drift);
  ASSERT_EQ(degraded.frames().size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_LT((degraded.frames()[i].odomTEgo.matrix() - expected[i].matrix()).norm(), 1e-9) << i;
    EXPECT_TRUE(degraded.frames()[i].covariance == plain.frames()[i].covariance) << i;
  }
  const double travelled = plainPoses.back().translation().norm();
  ASSERT_GT(travelled, 15.0);
  // 1 % longer over the drive, near enough on a straight-ish 3 s drive.
  EXPECT_NEAR(degraded.frames().back().odomTEgo.translation().norm() / travelled, 1.01, 0.002);
  ASSERT_GE(degraded.keyframes().size(), 2u);
  for (size_t k = 1; k < degraded.keyframes().size(); ++k) {
    const Keyframe& kf = degraded.keyframes()[k];
    const SE3 between = degraded.frames()[degraded.keyframes()[k - 1].frame].odomTEgo.inverse() * degraded.frames()[kf.frame].odomTEgo;
    EXPECT_TRUE(kf.previousTThis.isApprox(between, 1e-12)) << k;
  }
  OdometryOptions tooMuch;
  tooMuch.drift.scale = 0.5;
  EXPECT_THROW(Odometry{tooMuch}, Error);
}

}  // namespace hdprior
