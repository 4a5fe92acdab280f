#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "engine/io/argoverse_log.h"
#include "engine/odom/odometry.h"
#include "test_data.h"
#include "ui/session_runner.h"

namespace hdprior::test {
namespace {
namespace fs = std::filesystem;

// The app's worker: a job runs off the UI thread, can be cancelled between sweeps and resumed, and the
// session is readable only while no job runs.
TEST(SessionRunner, RunsCancelsAndResumesOffTheUiThread) {
  const ArgoverseLog log(sharedLog());
  ui::SessionRunner runner(log, Config{});
  EXPECT_EQ(runner.session(), nullptr);

  runner.run();
  runner.cancel();  // seen before the first sweep (the job first loads the map)
  EXPECT_TRUE(runner.busy());
  EXPECT_EQ(runner.session(), nullptr);
  runner.wait();
  ASSERT_TRUE(runner.poll());
  EXPECT_FALSE(runner.busy());
  EXPECT_TRUE(runner.error().empty()) << runner.error();
  EXPECT_EQ(runner.lastJob(), "cancelled at sweep 0");
  ASSERT_NE(runner.session(), nullptr);
  EXPECT_EQ(runner.session()->sweepsDone(), 0u);
  EXPECT_FALSE(runner.poll());  // nothing new

  runner.stepKeyframe();
  runner.wait();
  ASSERT_TRUE(runner.poll());
  EXPECT_EQ(runner.session()->sweepsDone(), 1u);
  EXPECT_EQ(runner.session()->matches().size(), 1u);

  runner.run();
  runner.wait();
  ASSERT_TRUE(runner.poll());
  EXPECT_TRUE(runner.session()->done());
  ASSERT_TRUE(runner.lastSolve().has_value());

  runner.restart(Config{});
  EXPECT_EQ(runner.session(), nullptr);
}

TEST(SessionRunner, AJobThatFailsLeavesItsMessage) {
  const ArgoverseLog log(sharedLog());
  Config config;
  config.match.cellSizes = {0.05};  // finer than the drivable raster: the map cannot have that NDT grid
  ui::SessionRunner runner(log, config);
  runner.run();
  runner.wait();
  ASSERT_TRUE(runner.poll());
  EXPECT_NE(runner.error().find("0.05"), std::string::npos) << runner.error();
  EXPECT_NE(runner.lastJob().find("failed"), std::string::npos);
  EXPECT_EQ(runner.session(), nullptr);
}

// The shared log with its second sweep corrupt: the app's run steps over it when the share allows
// (1 of 2 here), else the job fails with the one-line error naming the share; nothing crashes.
TEST(SessionRunner, AnUnreadableSweepIsSkippedOrFailsTheJob) {
  const fs::path dir = freshOutputDir("runner_bad_sweep") / "log";
  fs::create_directories(dir / "sensors" / "lidar");
  for (const char* entry : {"map", "calibration", "city_SE3_egovehicle.feather"})
    fs::create_symlink(fs::absolute(sharedLog() / entry), dir / entry);
  std::vector<fs::path> sweeps;
  for (const auto& e : fs::directory_iterator(sharedLog() / "sensors" / "lidar")) sweeps.push_back(e.path());
  std::sort(sweeps.begin(), sweeps.end());
  fs::copy_file(sweeps[0], dir / "sensors" / "lidar" / sweeps[0].filename());
  std::ofstream(dir / "sensors" / "lidar" / sweeps[1].filename()) << "not a feather file";
  const ArgoverseLog log(dir);

  Config lenient;
  lenient.maxUnreadableSweepShare = 0.5;
  ui::SessionRunner runner(log, lenient);
  runner.run();
  runner.wait();
  ASSERT_TRUE(runner.poll());
  EXPECT_TRUE(runner.error().empty()) << runner.error();
  EXPECT_EQ(runner.lastJob(), "ran 2 sweeps, 1 keyframes, 1 unreadable sweeps skipped");
  ASSERT_EQ(runner.session()->skippedSweeps().size(), 1u);
  EXPECT_EQ(runner.session()->odometryTrajectory().size(), 1u);

  ui::SessionRunner strict(log, Config{});
  strict.run();
  strict.wait();
  ASSERT_TRUE(strict.poll());
  EXPECT_NE(strict.error().find(sweeps[1].filename().string()), std::string::npos) << strict.error();
  EXPECT_NE(strict.error().find("1 of the log's 2 sweeps (50.0 %) are unreadable"), std::string::npos) << strict.error();
}

}  // namespace
}  // namespace hdprior::test
