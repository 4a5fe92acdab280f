#include <gtest/gtest.h>

#include "engine/io/argoverse_log.h"
#include "engine/pipeline/pipeline_run.h"
#include "engine/sim/log_writer.h"
#include "test_data.h"

namespace hdprior {

// Integration: the odometry on a short simulated town drive (default noise) stays within a drift
// bound and keeps its local map bounded.
TEST(SimulatedDriveOdometry, ShortTownDriveDriftBound) {
  SimulationOptions sim;
  sim.townSeed = 7;
  sim.seed = 1;
  sim.seconds = 12.0;
  sim.outDir = test::freshOutputDir("odom_sim_drive");
  const SimulationResult log = simulateLog(sim);
  const ArgoverseLog argo(log.dir);
  const PipelineRun run = runPipeline(argo, Config{}, {.priors = false});
  const RunMetrics m = evaluateRun(run);
  const TrajectoryEvaluation& e = m.odometry;
  std::printf("simulated %zu sweeps, path %.1f m: ATE rmse %.3f m max %.3f m; RPE10 %.2f %% yaw %.3f deg/100m; "
              "%zu keyframes; local map <= %zu points; %.1f sweeps/s\n",
              run.estimate.size(), e.pathLength, e.ate.translation.rmse, e.ate.translation.max, e.rpe10.translationPercent,
              e.rpe10.yawDegPer100m, run.odometry->keyframes().size(), run.maxLocalMapPoints,
              double(run.estimate.size()) / run.times.pipelineS);
  ASSERT_GT(e.pathLength, 30.0);
  EXPECT_LT(e.rpe10.translationPercent, 2.0);
  EXPECT_LT(e.ate.translation.max, 0.02 * e.pathLength);
  EXPECT_LT(e.rpe10.yawDegPer100m, 2.0);
  EXPECT_GE(run.odometry->keyframes().size(), size_t(e.pathLength / 2.0 * 0.8));
  for (const Keyframe& k : run.odometry->keyframes()) {
    EXPECT_FALSE(k.submapFrames.empty());
    EXPECT_TRUE(k.relativeCovariance.allFinite());
  }
}

}  // namespace hdprior
