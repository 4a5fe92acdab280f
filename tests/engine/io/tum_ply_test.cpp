#include <gtest/gtest.h>

#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include "engine/error.h"
#include "engine/io/ply_writer.h"
#include "engine/io/tum_trajectory.h"
#include "test_data.h"

namespace hdprior {

TEST(TumTrajectory, RoundTripKeepsNanosecondsAndPoses) {
  std::vector<int64_t> t = {315966265259836000, 315966265360032001, 315966265460032999};
  std::vector<SE3> poses;
  for (int i = 0; i < 3; ++i) {
    poses.push_back(makeSE3(Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * i, Eigen::Vector3d(1, 2, 3).normalized())),
                            Eigen::Vector3d(5172.668 + i, 2300.5 - i, 69.07)));
  }
  const auto dir = test::freshOutputDir("tum_round_trip");
  writeTum(dir / "a.tum", PoseTrajectory(t, poses));
  const PoseTrajectory back = readTum(dir / "a.tum");
  ASSERT_EQ(back.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(back.timestamps()[i], t[i]);
    EXPECT_LT((back.poses()[i].translation() - poses[i].translation()).norm(), 1e-6);
    EXPECT_TRUE(back.poses()[i].rotation().isApprox(poses[i].rotation(), 1e-8));
  }
  EXPECT_EQ(formatTum(back), formatTum(PoseTrajectory(t, poses)));
}

TEST(TumTrajectory, BadLinesNameTheLine) {
  EXPECT_THROW(parseTum("1.0 1 2 3 0 0 0\n", "x.tum"), Error);
  EXPECT_THROW(parseTum("1.0 1 2 3 0 0 0 5\n", "x.tum"), Error);  // not a unit quaternion
  EXPECT_THROW(parseTum("abc 1 2 3 0 0 0 1\n", "x.tum"), Error);
  try {
    parseTum("# c\n1.0 0 0 0 0 0 0 1\n0.5 0 0 0 0 0 0 1\n", "x.tum");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("x.tum"), std::string::npos);
  }
}

TEST(PlyWriter, PclReadsPointsAndIntensity) {
  std::vector<Eigen::Vector3f> pts = {{1, 2, 3}, {-4.5f, 5, 6.25f}, {7, 8, 9}};
  const auto dir = test::freshOutputDir("ply_writer");
  writePly(dir / "a.ply", pts, {10, 20, 30});
  pcl::PointCloud<pcl::PointXYZI> cloud;
  ASSERT_EQ(pcl::io::loadPLYFile(( dir / "a.ply").string(), cloud), 0);
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_FLOAT_EQ(cloud[1].x, -4.5f);
  EXPECT_FLOAT_EQ(cloud[1].z, 6.25f);
  EXPECT_FLOAT_EQ(cloud[2].intensity, 30.f);
  writePly(dir / "b.ply", pts);
  pcl::PointCloud<pcl::PointXYZ> plain;
  ASSERT_EQ(pcl::io::loadPLYFile((dir / "b.ply").string(), plain), 0);
  EXPECT_FLOAT_EQ(plain[2].y, 8.f);
  EXPECT_THROW(writePly(dir / "c.ply", pts, {1}), Error);
}

}  // namespace hdprior
