#include <gtest/gtest.h>

#include <cmath>

#include "engine/io/argoverse_log.h"
#include "engine/odom/odometry.h"
#include "test_data.h"

namespace hdprior {

// Acceptance check on real data: the two consecutive real sweeps of the shared log, registered by the
// odometry, give the ground-truth relative pose within 0.05 m and 0.2 deg.
TEST(RealSweepsOdometry, RelativePoseMatchesGroundTruth) {
  const ArgoverseLog log(test::sharedLog());
  ASSERT_EQ(log.sweepCount(), 2u);
  Odometry odometry;
  odometry.registerSweep(*log.sweep(0));
  const OdometryFrame& f = odometry.registerSweep(*log.sweep(1));
  const SE3 gt = log.cityTEgo().at(log.sweepTimestamps()[0]).inverse() * log.cityTEgo().at(log.sweepTimestamps()[1]);
  const SE3 error = gt.inverse() * f.odomTEgo;
  const double translationError = error.translation().norm();
  const double angleErrorDeg = Eigen::AngleAxisd(error.rotation()).angle() * 180 / M_PI;
  std::printf("GT motion %.4f m; estimate %.4f %.4f %.4f; translation error %.4f m, rotation error %.4f deg; "
              "%d plane residuals\n",
              gt.translation().norm(), f.odomTEgo.translation().x(), f.odomTEgo.translation().y(),
              f.odomTEgo.translation().z(), translationError, angleErrorDeg, f.planeResiduals);
  EXPECT_LT(translationError, 0.05);
  EXPECT_LT(angleErrorDeg, 0.2);
  EXPECT_GT(f.planeResiduals, 500);
}

}  // namespace hdprior
