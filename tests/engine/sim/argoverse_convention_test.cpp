// How Argoverse 2 stores a sweep, checked on the two real consecutive sweeps of the shared
// log; the simulator writes its sweeps the same way (engine/sim/sweep_simulator.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "engine/io/argoverse_log.h"
#include "sweep_agreement.h"
#include "test_data.h"

namespace hdprior {
namespace {

double azimuthDeg(const LidarPoint& p, const Eigen::Vector3d& sensor) {
  return std::atan2(double(p.y) - sensor.y(), double(p.x) - sensor.x()) * 180.0 / std::numbers::pi;
}

TEST(ArgoverseConvention, OffsetsRunFromTheSweepTimestampOverOnePeriod) {
  const ArgoverseLog log(test::sharedLog());
  for (size_t i = 0; i < log.sweepCount(); ++i) {
    const auto sweep = log.sweep(i);
    int32_t lo = INT32_MAX, hi = INT32_MIN;
    for (const LidarPoint& p : sweep->points) {
      lo = std::min(lo, p.offsetNs);
      hi = std::max(hi, p.offsetNs);
    }
    EXPECT_GE(lo, 0);            // the sweep timestamp is the start of the sweep
    EXPECT_LT(hi, 110'000'000);  // one revolution at 10 Hz
    EXPECT_GT(hi, 95'000'000);
  }
}

// Each lidar turns clockwise seen from above (azimuth decreasing with offset_ns), the two
// half a turn apart. Printed: the azimuth at offset 0 for each lidar.
TEST(ArgoverseConvention, BothLidarsTurnClockwiseHalfATurnApart) {
  const ArgoverseLog log(test::sharedLog());
  const auto sweep = log.sweep(0);
  double startAzimuth[2] = {0.0, 0.0};
  for (int unit = 0; unit < 2; ++unit) {
    const Eigen::Vector3d sensor = log.calibration().at(unit == 0 ? "up_lidar" : "down_lidar").translation();
    std::printf("[ info ] %s at (%.3f, %.3f, %.3f) in the ego frame\n", unit == 0 ? "up_lidar" : "down_lidar",
                sensor.x(), sensor.y(), sensor.z());
    // Circular mean azimuth of the returns in 10 ms bins of offset_ns.
    std::vector<Eigen::Vector2d> bins(10, Eigen::Vector2d::Zero());
    for (const LidarPoint& p : sweep->points) {
      if ((p.laserNumber >= 32) != (unit == 1) || std::hypot(double(p.x), double(p.y)) < 3.0) continue;
      const int b = std::min(9, int(p.offsetNs / 10'000'000));
      const double a = azimuthDeg(p, sensor) * std::numbers::pi / 180.0;
      bins[size_t(b)] += Eigen::Vector2d(std::cos(a), std::sin(a));
    }
    std::vector<double> az;
    for (const Eigen::Vector2d& v : bins) az.push_back(std::atan2(v.y(), v.x()) * 180.0 / std::numbers::pi);
    // Bin means wander with the scene (returns are not uniform in azimuth), but every step
    // turns clockwise and together they make 9/10 of a turn.
    double total = 0.0;
    for (size_t b = 1; b < az.size(); ++b) {
      const double step = std::remainder(az[b] - az[b - 1], 360.0);
      EXPECT_LT(step, -15.0) << "unit " << unit << " bin " << b;
      EXPECT_GT(step, -60.0) << "unit " << unit << " bin " << b;
      total += step;
    }
    EXPECT_NEAR(total, -324.0, 15.0) << "unit " << unit;
    std::printf("[ info ] %s: azimuth at offset 5 ms %.1f deg, at 95 ms %.1f deg\n", unit == 0 ? "up_lidar" : "down_lidar",
                az[0], az[9]);
    startAzimuth[unit] = az[0] + 18.0;  // 5 ms earlier at 36 degrees per 10 ms
  }
  EXPECT_NEAR(std::abs(std::remainder(startAzimuth[0] - startAzimuth[1], 360.0)), 180.0, 20.0);
}

// Placing each sweep with the pose at the sweep timestamp (points already motion-
// compensated) makes the two consecutive sweeps agree better than placing every return with
// the pose at its own time (raw, uncompensated points).
TEST(ArgoverseConvention, SweepsAreMotionCompensatedToTheSweepTimestamp) {
  const ArgoverseLog log(test::sharedLog());
  const auto a = log.sweep(0), b = log.sweep(1);
  const PoseTrajectory& T = log.cityTEgo();
  const double speed = (T.at(b->timestampNs).translation() - T.at(a->timestampNs).translation()).norm() /
                       (double(b->timestampNs - a->timestampNs) * 1e-9);
  const double dCompensated = test::medianNearest(T, *a, *b, test::Placement::AtSweepTimestamp);
  const double dRaw = test::medianNearest(T, *a, *b, test::Placement::AtReturnTime);
  std::printf("[ info ] ego speed %.2f m/s; median nearest distance between the sweeps: compensated %.4f m, raw %.4f m\n",
              speed, dCompensated, dRaw);
  EXPECT_LT(dCompensated, dRaw);
}

}  // namespace
}  // namespace hdprior
