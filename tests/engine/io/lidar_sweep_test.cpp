#include "engine/io/lidar_sweep.h"

#include <gtest/gtest.h>

#include "engine/error.h"
#include "engine/io/ego_poses.h"
#include "engine/io/file_bytes.h"
#include "test_data.h"

namespace hdprior {
namespace {

TEST(LidarSweep, WriterRoundTripsRealSweepExactly) {
  const auto path = test::sharedLog() / "sensors/lidar/315966265259836000.feather";
  const LidarSweep a = readLidarSweep(path);
  const auto out = test::freshOutputDir("sweep_roundtrip") / "315966265259836000.feather";
  writeLidarSweep(out, a);
  const LidarSweep b = readLidarSweep(out);
  ASSERT_EQ(b.points.size(), a.points.size());
  EXPECT_EQ(b.timestampNs, a.timestampNs);
  for (size_t i = 0; i < a.points.size(); ++i) {
    const LidarPoint &p = a.points[i], &q = b.points[i];
    ASSERT_TRUE(p.x == q.x && p.y == q.y && p.z == q.z && p.intensity == q.intensity &&
                p.laserNumber == q.laserNumber && p.offsetNs == q.offsetNs)
        << "row " << i;
  }
}

TEST(LidarSweep, FileNameMustBeATimestamp) {
  const auto dir = test::freshOutputDir("sweep_name");
  std::filesystem::copy_file(test::sharedLog() / "sensors/lidar/315966265259836000.feather", dir / "abc.feather");
  EXPECT_THROW(readLidarSweep(dir / "abc.feather"), Error);
}

TEST(EgoPoses, WriterRoundTripsPosesAndCalibration) {
  const PoseTrajectory a = readEgoPoses(test::sharedLog() / "city_SE3_egovehicle.feather");
  const auto dir = test::freshOutputDir("poses_roundtrip");
  writeEgoPoses(dir / "poses.feather", a);
  const PoseTrajectory b = readEgoPoses(dir / "poses.feather");
  ASSERT_EQ(b.size(), a.size());
  EXPECT_EQ(b.timestamps(), a.timestamps());
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_TRUE(b.poses()[i].isApprox(a.poses()[i], 1e-12)) << i;
  }
  const SensorCalibration c = readSensorCalibration(test::sharedLog() / "calibration/egovehicle_SE3_sensor.feather");
  writeSensorCalibration(dir / "calib.feather", c);
  const SensorCalibration d = readSensorCalibration(dir / "calib.feather");
  ASSERT_EQ(d.size(), c.size());
  for (const auto& [name, pose] : c) EXPECT_TRUE(d.at(name).isApprox(pose, 1e-12)) << name;
}

}  // namespace
}  // namespace hdprior
