#include <gtest/gtest.h>

#include "engine/io/argoverse_log.h"
#include "engine/odom/odometry.h"
#include "test_data.h"
#include "ui/session_runner.h"

namespace hdprior::test {
namespace {

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

}  // namespace
}  // namespace hdprior::test
