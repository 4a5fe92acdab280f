#include <gtest/gtest.h>

#include <fstream>

#include "engine/error.h"
#include "engine/io/kitti_trajectory.h"
#include "engine/io/seconds_text.h"
#include "engine/io/trajectory_file.h"
#include "engine/io/tum_trajectory.h"
#include "error_message.h"
#include "test_data.h"

namespace hdprior {
namespace fs = std::filesystem;

namespace {

std::vector<SE3> somePoses(size_t n) {
  std::vector<SE3> poses;
  for (size_t i = 0; i < n; ++i) {
    poses.push_back(makeSE3(Eigen::Quaterniond(Eigen::AngleAxisd(0.4 * double(i) - 1.0, Eigen::Vector3d(1, 2, 3 + double(i)).normalized())),
                            Eigen::Vector3d(5172.668 + 1.7 * double(i), 2300.5 - 0.3 * double(i), 69.07 + 0.01 * double(i))));
  }
  return poses;
}

void expectSamePoses(const std::vector<SE3>& a, const std::vector<SE3>& b, double translation, double rotation) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_LT((a[i].translation() - b[i].translation()).norm(), translation) << i;
    EXPECT_LT(Eigen::AngleAxisd(a[i].rotation().transpose() * b[i].rotation()).angle(), rotation) << i;
  }
}

using test::errorOf;

const std::vector<int64_t> kStamps = {315966265259836000, 315966265360032001, 315966265460032999};

}  // namespace

TEST(SecondsText, ReadsDecimalAndExponentNotationExactlyToTheNanosecond) {
  EXPECT_EQ(parseSecondsNs("315966265.259836001"), 315966265259836001);
  EXPECT_EQ(parseSecondsNs("3.15966265259836001e+08"), 315966265259836001);
  EXPECT_EQ(parseSecondsNs("1.317384506000000000e+09"), 1317384506000000000);  // numpy's savetxt default
  EXPECT_EQ(parseSecondsNs("12"), 12000000000);
  EXPECT_EQ(parseSecondsNs("12."), 12000000000);
  EXPECT_EQ(parseSecondsNs(".5"), 500000000);
  EXPECT_EQ(parseSecondsNs("0.05"), 50000000);
  EXPECT_EQ(parseSecondsNs("1.0000000005"), 1000000001);  // rounds to the nearest ns
  EXPECT_EQ(parseSecondsNs("1.00000000049"), 1000000000);
  EXPECT_EQ(parseSecondsNs("5e-10"), 1);
  EXPECT_EQ(parseSecondsNs("0"), 0);
  EXPECT_EQ(parseSecondsNs("0e99999"), std::nullopt);  // exponent beyond what is read
  for (const char* bad : {"", ".", "-1", "+1", "1e", "1e+", "abc", "1.2.3", "1,5", "nan", "inf", "1e10", "9300000000"}) {
    EXPECT_EQ(parseSecondsNs(bad), std::nullopt) << bad;
  }
  EXPECT_EQ(formatSecondsNs(315966265259836001), "315966265.259836001");
  EXPECT_EQ(parseSecondsNs(formatSecondsNs(9223372036854775807)), 9223372036854775807);
}

TEST(TumTrajectory, RoundTripInAnyNotationAndWithComments) {
  const std::vector<SE3> poses = somePoses(3);
  const std::string text = formatTum(PoseTrajectory(kStamps, poses));
  const PoseTrajectory back = parseTum("# comment\n\n" + text + "   \n# end\n", "a.tum");
  EXPECT_EQ(back.timestamps(), kStamps);
  expectSamePoses(back.poses(), poses, 1e-6, 1e-8);
  // evo / numpy style: exponent timestamps, CRLF line endings, tabs
  const PoseTrajectory numpy = parseTum("3.159662652598360000e+08\t1 2 3 0 0 0 1\r\n3.159662653600320010e+08 1 2 3 0 0 0 1\r\n", "b.tum");
  EXPECT_EQ(numpy.timestamps(), (std::vector<int64_t>{315966265259836000, 315966265360032001}));
}

TEST(TumTrajectory, EachBadLineIsAnErrorNamingTheFileAndLine) {
  const std::string ok = "1.0 0 0 0 0 0 0 1\n";
  const struct {
    std::string text, message;
  } cases[] = {
      {ok + "2.0 0 0 0 0 0 1\n", "x.tum:2: expected 8 fields 'timestamp tx ty tz qx qy qz qw', found 7"},
      {ok + "2.0 0 0 0 0 0 0 1 9\n", "x.tum:2: expected 8 fields"},
      {ok + "2.0 nan 0 0 0 0 0 1\n", "x.tum:2: tx is not finite (nan)"},
      {ok + "2.0 0 0 -inf 0 0 0 1\n", "x.tum:2: tz is not finite (-inf)"},
      {ok + "2.0 0 0 0 0 0 0 1.01\n", "x.tum:2: the quaternion's norm is 1.01 (more than 1e-3 from unit length)"},
      {ok + "2.0 0 0 0 0 0 0 0\n", "x.tum:2: the quaternion's norm is 0"},
      {ok + "2.0 0 zero 0 0 0 0 1\n", "x.tum:2: 'zero' is not a number (field ty)"},
      {ok + "abc 0 0 0 0 0 0 1\n", "x.tum:2: bad timestamp 'abc'"},
      {"# h\n" + ok + "1.0 0 0 0 0 0 0 1\n", "x.tum:3: timestamp 1.000000000 s is not after the previous pose's 1.000000000 s"},
      {ok + "0.5 0 0 0 0 0 0 1\n", "x.tum:2: timestamp 0.500000000 s is not after"},
  };
  for (const auto& c : cases) {
    const std::string message = errorOf([&] { parseTum(c.text, "x.tum"); });
    EXPECT_NE(message.find(c.message), std::string::npos) << c.text << " -> " << message;
  }
  // Within 1e-3 of unit length: normalised.
  const PoseTrajectory nearUnit = parseTum("1.0 0 0 0 0 0 0 1.0009\n", "x.tum");
  EXPECT_NEAR(Eigen::Quaterniond(nearUnit.poses()[0].rotation()).norm(), 1.0, 1e-12);
}

TEST(KittiTrajectory, RoundTripOfPosesAndTimes) {
  const std::vector<SE3> poses = somePoses(5);
  const std::vector<SE3> back = parseKitti(formatKitti(poses), "a.txt");
  expectSamePoses(back, poses, 1e-7, 1e-10);
  const std::vector<int64_t> times = {1, 1000000000, 315966265259836000, 315966265360032001, 315966265460032999};
  EXPECT_EQ(parseTimes(formatTimes(times), "times.txt"), times);
  const PoseTrajectory t = kittiTrajectory(back, times, "a.txt", "timestamps");
  EXPECT_EQ(t.timestamps(), times);
}

TEST(KittiTrajectory, EachBadLineIsAnErrorNamingTheFileAndLine) {
  const std::string ok = "1 0 0 0 0 1 0 0 0 0 1 0\n";
  const struct {
    std::string text, message;
  } cases[] = {
      {ok + "1 0 0 0 0 1 0 0 0 0 1\n", "p.txt:2: expected 12 fields (a 3x4 pose matrix row by row), found 11"},
      {ok + "1 0 0 nan 0 1 0 0 0 0 1 0\n", "p.txt:2: tx is not finite (nan)"},
      {ok + "1 0 0 0 0 1 0 0 0 0 1 x\n", "p.txt:2: 'x' is not a number (field tz)"},
      {ok + "1.1 0 0 0 0 1 0 0 0 0 1 0\n", "p.txt:2: the 3x3 part is not a rotation"},
      {ok + "1 0 0 0 0 1 0 0 0 0 -1 0\n", "p.txt:2: the 3x3 part is not a rotation"},  // a reflection
  };
  for (const auto& c : cases) {
    const std::string message = errorOf([&] { parseKitti(c.text, "p.txt"); });
    EXPECT_NE(message.find(c.message), std::string::npos) << c.text << " -> " << message;
  }
  EXPECT_NE(errorOf([] { parseTimes("1.0\n0.5\n", "t.txt"); }).find("t.txt:2: timestamp 0.500000000 s is not after"), std::string::npos);
  EXPECT_NE(errorOf([] { parseTimes("1.0 2.0\n", "t.txt"); }).find("t.txt:1: expected one timestamp"), std::string::npos);
  EXPECT_NE(errorOf([] { kittiTrajectory(somePoses(3), {1, 2}, "p.txt", "sweeps in the log"); })
                .find("p.txt: 3 poses but 2 sweeps in the log"),
            std::string::npos);
}

TEST(TrajectoryFile, FormatByExtensionThenByFieldCount) {
  EXPECT_EQ(detectTrajectoryFormat("1 2 3 4 5 6 7 8 9 10 11 12\n", "a.tum"), TrajectoryFormat::Tum);
  EXPECT_EQ(detectTrajectoryFormat("1 2 3 4 5 6 7 8\n", "a.kitti"), TrajectoryFormat::Kitti);
  EXPECT_EQ(detectTrajectoryFormat("# t x y z qx qy qz qw\n1 2 3 4 5 6 7 8\n", "a.txt"), TrajectoryFormat::Tum);
  EXPECT_EQ(detectTrajectoryFormat("1 2 3 4 5 6 7 8 9 10 11 12\n", "a.txt"), TrajectoryFormat::Kitti);
  EXPECT_NE(errorOf([] { detectTrajectoryFormat("\n1 2 3\n", "a.txt"); }).find("a.txt:2: 3 fields: neither TUM (8) nor KITTI (12)"),
            std::string::npos);
  EXPECT_NE(errorOf([] { detectTrajectoryFormat("# only\n", "a.txt"); }).find("a.txt: no poses"), std::string::npos);
  EXPECT_EQ(parseTrajectoryFormat("kitti", "o"), TrajectoryFormat::Kitti);
  EXPECT_NE(errorOf([] { parseTrajectoryFormat("euroc", "option --odometry-format"); })
                .find("option --odometry-format: must be tum or kitti, not 'euroc'"),
            std::string::npos);
}

TEST(TrajectoryFile, ReadsTumAndKittiAndNeedsTwoPoses) {
  const fs::path dir = test::freshOutputDir("trajectory_file");
  const std::vector<SE3> poses = somePoses(3);
  writeTum(dir / "a.tum", PoseTrajectory(kStamps, poses));
  std::ofstream(dir / "a.txt") << formatKitti(poses);
  std::ofstream(dir / "times.txt") << formatTimes({10, 20, 30});
  const TrajectoryFileContents tum = readTrajectoryFile({dir / "a.tum", std::nullopt, std::nullopt}, {});
  EXPECT_EQ(tum.format, TrajectoryFormat::Tum);
  EXPECT_EQ(tum.trajectory.timestamps(), kStamps);
  const TrajectoryFileContents kitti = readTrajectoryFile({dir / "a.txt", std::nullopt, std::nullopt}, kStamps);
  EXPECT_EQ(kitti.format, TrajectoryFormat::Kitti);
  EXPECT_EQ(kitti.trajectory.timestamps(), kStamps);
  expectSamePoses(kitti.trajectory.poses(), tum.trajectory.poses(), 1e-6, 1e-8);
  const TrajectoryFileContents timed = readTrajectoryFile({dir / "a.txt", TrajectoryFormat::Kitti, dir / "times.txt"}, {});
  EXPECT_EQ(timed.trajectory.timestamps(), (std::vector<int64_t>{10, 20, 30}));

  EXPECT_NE(errorOf([&] { readTrajectoryFile({dir / "a.txt", std::nullopt, std::nullopt}, {1, 2}); })
                .find("a.txt: 3 poses but 2 sweeps in the log"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { readTrajectoryFile({dir / "a.tum", std::nullopt, dir / "times.txt"}, {}); })
                .find("times.txt: a times file is only for KITTI poses"),
            std::string::npos);
  std::ofstream(dir / "one.tum") << "# one pose\n1.0 0 0 0 0 0 0 1\n";
  EXPECT_NE(errorOf([&] { readTrajectoryFile({dir / "one.tum", std::nullopt, std::nullopt}, {}); })
                .find("one.tum: 1 pose: at least 2 are needed"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { readTrajectoryFile({dir / "missing.tum", std::nullopt, std::nullopt}, {}); }).find("missing.tum"),
            std::string::npos);
}

}  // namespace hdprior
