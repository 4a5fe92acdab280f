// A sweep taken while driving at 8 m/s towards a wall: every return is stored in the ego
// frame at the sweep timestamp (motion-compensated, like Argoverse 2), so the wall comes out
// flat; placing returns with the pose at their own time instead would smear it by up to 0.8 m.
#include "engine/sim/sweep_simulator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/map/drivable_raster.h"
#include "../map/synthetic_maps.h"

namespace hdprior {
namespace {

constexpr int64_t kStart = 1'000'000'000'000;

Scene wallScene() {
  const VectorMap map = test::mapOf({test::rectangle(-80, -80, 80, 80)});
  const DrivableRaster raster = DrivableRaster::build(map, {}, "test");
  GridGeometry g;
  g.origin = {-100, -100};
  g.resolution = 0.5;
  g.cols = g.rows = 400;
  Scene scene(g, std::vector<float>(g.cellCount(), 0.0f), BoundaryDistance::build(raster), 4.0, 1);
  scene.addBox({Eigen::Vector2d(30.5, 0), 0.0, Eigen::Vector2d(1.0, 40.0), -1.0, 10.0, 50});  // face at x = 29.5
  scene.index();
  return scene;
}

PoseTrajectory driveAlongX(double speed) {
  std::vector<int64_t> t;
  std::vector<SE3> p;
  for (int i = 0; i <= 60; ++i) {
    t.push_back(kStart + int64_t(i) * 5'000'000);
    p.push_back(makeSE3(Eigen::Quaterniond::Identity(), Eigen::Vector3d(speed * i * 0.005, 0, 0.32)));
  }
  return PoseTrajectory(t, p);
}

TEST(SweepSimulator, ReturnsAreMotionCompensatedToTheSweepTimestamp) {
  const Scene scene = wallScene();
  const PoseTrajectory T = driveAlongX(8.0);
  const SimulatedSweep s = simulateSweep(scene, argoverseLikeLidar(), T, kStart, SweepNoise{0.0, 0.0}, 1);
  ASSERT_EQ(s.labels.size(), s.sweep.points.size());
  double worstCompensated = 0.0, worstRaw = 0.0;
  size_t wall = 0;
  for (size_t i = 0; i < s.labels.size(); ++i) {
    const LidarPoint& p = s.sweep.points[i];
    if (s.labels[i] != uint8_t(PointLabel::Object) || std::abs(p.y) > 20.0) continue;
    ++wall;
    const Eigen::Vector3d q(p.x, p.y, p.z);
    worstCompensated = std::max(worstCompensated, std::abs((T.at(kStart) * q).x() - 29.5));
    worstRaw = std::max(worstRaw, std::abs((T.at(kStart + p.offsetNs) * q).x() - 29.5));
  }
  EXPECT_GT(wall, 1000u);
  EXPECT_LT(worstCompensated, 0.02);  // float16 storage: 1/64 m steps at 16-32 m
  EXPECT_GT(worstRaw, 0.3);
}

TEST(SweepSimulator, FillsLaserNumbersOffsetsAndLabelsLikeArgoverse) {
  const Scene scene = wallScene();
  const SimulatedSweep s = simulateSweep(scene, argoverseLikeLidar(), driveAlongX(0.0), kStart, SweepNoise{}, 1);
  std::vector<size_t> perLaser(64, 0);
  for (size_t i = 0; i < s.sweep.points.size(); ++i) {
    const LidarPoint& p = s.sweep.points[i];
    ASSERT_LT(p.laserNumber, 64);
    ++perLaser[p.laserNumber];
    ASSERT_GE(p.offsetNs, 0);
    ASSERT_LT(p.offsetNs, 100'000'000);
    ASSERT_LE(s.labels[i], uint8_t(PointLabel::Object));
  }
  // Every beam but the steepest upward ones finds the ground or the wall.
  size_t lasersWithReturns = 0;
  for (size_t n : perLaser) lasersWithReturns += n > 0;

  EXPECT_GE(lasersWithReturns, 60u);
  // Deterministic by seed, different across seeds.
  const SimulatedSweep again = simulateSweep(scene, argoverseLikeLidar(), driveAlongX(0.0), kStart, SweepNoise{}, 1);
  const SimulatedSweep other = simulateSweep(scene, argoverseLikeLidar(), driveAlongX(0.0), kStart, SweepNoise{}, 2);
  const auto same = [](const LidarSweep& a, const LidarSweep& b) {
    return std::equal(a.points.begin(), a.points.end(), b.points.begin(), b.points.end(),
                      [](const LidarPoint& p, const LidarPoint& q) {
                        return p.x == q.x && p.y == q.y && p.z == q.z && p.intensity == q.intensity &&
                               p.laserNumber == q.laserNumber && p.offsetNs == q.offsetNs;
                      });
  };
  EXPECT_TRUE(same(again.sweep, s.sweep));
  EXPECT_FALSE(same(other.sweep, s.sweep));
}

// A sensor that is not what it believes (engine/sim/scene_variation.h): with a range bias on
// the up lidar, each of its points moves 3 cm out along its beam; with zero errors the
// imperfect sensor's path places every point where the ideal one does.
TEST(SweepSimulator, RangeBiasMovesEachPointAlongItsBeam) {
  const Scene scene = wallScene();
  const PoseTrajectory T = driveAlongX(0.0);
  const LidarModel ideal = argoverseLikeLidar();
  LidarModel biased = ideal, zero = ideal;
  biased.units[0].rangeBiases.assign(32, 0.03);
  zero.units[0].trueEgoTSensor = zero.units[0].egoTSensor;
  const SimulatedSweep a = simulateSweep(scene, ideal, T, kStart, SweepNoise{0.0, 0.0}, 1);
  const SimulatedSweep b = simulateSweep(scene, biased, T, kStart, SweepNoise{0.0, 0.0}, 1);
  const SimulatedSweep c = simulateSweep(scene, zero, T, kStart, SweepNoise{0.0, 0.0}, 1);
  ASSERT_EQ(a.sweep.points.size(), b.sweep.points.size());
  ASSERT_EQ(a.sweep.points.size(), c.sweep.points.size());
  const Eigen::Vector3d up = ideal.units[0].egoTSensor.translation();
  size_t moved = 0;
  for (size_t i = 0; i < a.sweep.points.size(); ++i) {
    const LidarPoint &p = a.sweep.points[i], &q = b.sweep.points[i], &r = c.sweep.points[i];
    const Eigen::Vector3d pa(p.x, p.y, p.z), pb(q.x, q.y, q.z), pc(r.x, r.y, r.z);
    ASSERT_EQ(p.laserNumber, q.laserNumber);
    EXPECT_LT((pc - pa).norm(), 2e-4) << i;
    if (p.laserNumber < 32) {
      EXPECT_NEAR((pb - up).norm() - (pa - up).norm(), 0.03, 2e-4) << i;
      EXPECT_NEAR((pb - pa).norm(), 0.03, 2e-4) << i;
      ++moved;
    } else {
      EXPECT_LT((pb - pa).norm(), 1e-6) << i;
    }
  }
  EXPECT_GT(moved, 10000u);
}

}  // namespace
}  // namespace hdprior
