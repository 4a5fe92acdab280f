#include <gtest/gtest.h>

#include "engine/io/argoverse_log.h"
#include "engine/odom/deskew.h"
#include "engine/odom/keyframe.h"
#include "engine/odom/odometry.h"
#include "test_data.h"

namespace hdprior {

TEST(Deskew, MovesPointsByTheFractionOfTheSweepMotion) {
  SE3 motion = SE3::Identity();
  motion.translation() = Eigen::Vector3d(1.0, 0, 0);
  motion.linear() = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  LidarPoint p;
  p.x = 10;
  p.offsetNs = 50'000'000;  // half a 100 ms sweep: half the motion
  const Eigen::Vector3f q = deskewPoint(p, motion, 1e8);
  const Eigen::Vector3d expected = Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitZ()) * Eigen::Vector3d(10, 0, 0) + Eigen::Vector3d(0.5, 0, 0);
  EXPECT_NEAR((q.cast<double>() - expected).norm(), 0, 1e-5);
  const auto all = deskewSweep({p, LidarPoint{}}, motion, 1e8);
  EXPECT_NEAR((all[0].cast<double>() - expected).norm(), 0, 2e-3);  // sampled motion: 1/256 of the sweep
  EXPECT_NEAR(all[1].norm(), 0, 1e-6);
  EXPECT_TRUE(scaleMotion(motion, 1.0).isApprox(motion, 1e-12));
}

// The stored real points are already compensated to the sweep timestamp (the Argoverse 2
// convention): deskewing them again (constant_velocity) distorts sweep 1 against sweep 0 and must
// register worse than "none". Measured: 0.0058 m / 0.024 deg (none) vs 0.054 m / 0.216 deg.
TEST(Deskew, RealSweepsAgreeWithTheCompensatedConvention) {
  const ArgoverseLog log(test::sharedLog());
  const SE3 gt = log.cityTEgo().at(log.sweepTimestamps()[0]).inverse() * log.cityTEgo().at(log.sweepTimestamps()[1]);
  double error[2];
  for (int mode = 0; mode < 2; ++mode) {
    OdometryOptions o;
    o.deskew.mode = mode == 0 ? "none" : "constant_velocity";
    Odometry odometry(o);
    odometry.registerSweep(*log.sweep(0));
    const SE3 e = gt.inverse() * odometry.registerSweep(*log.sweep(1)).odomTEgo;
    error[mode] = e.translation().norm();
    std::printf("deskew %s: translation error %.4f m, rotation error %.4f deg\n", o.deskew.mode.c_str(), error[mode],
                Eigen::AngleAxisd(e.rotation()).angle() * 180 / M_PI);
  }
  EXPECT_LT(error[0], 0.05);
  EXPECT_LT(error[0], error[1]);
}

TEST(Keyframes, DistanceAndRotationThresholds) {
  const KeyframeOptions o;
  SE3 b = SE3::Identity();
  b.translation().x() = 1.9;
  EXPECT_FALSE(isNewKeyframe(SE3::Identity(), b, o));
  b.translation().x() = 2.0;
  EXPECT_TRUE(isNewKeyframe(SE3::Identity(), b, o));
  SE3 r = SE3::Identity();
  r.linear() = Eigen::AngleAxisd(10.5 * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_TRUE(isNewKeyframe(SE3::Identity(), r, o));
  // Relative covariance: identity relative pose adds the two covariances.
  const Eigen::Matrix<double, 6, 6> I = Eigen::Matrix<double, 6, 6>::Identity();
  EXPECT_TRUE(relativeCovariance(SE3::Identity(), I, 2 * I).isApprox(3 * I));
}

}  // namespace hdprior
