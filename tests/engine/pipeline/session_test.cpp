#include <gtest/gtest.h>

#include <atomic>

#include <unistd.h>

#include "engine/error.h"
#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/map/hd_map.h"
#include "engine/odom/odometry.h"
#include "engine/pipeline/pipeline_run.h"
#include "engine/pipeline/session.h"
#include "test_data.h"

namespace hdprior {

// The Session the app and the CLI drive: stepping, cancelling, re-optimising and re-matching a
// keyframe give the same numbers as one uninterrupted run.
class SessionTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    log_ = std::make_unique<ArgoverseLog>(test::simulatedTownDrive("session", 2, 3, 6.0).log);
    map_ = loadPriorMap(*log_, Config{});
  }
  static void TearDownTestSuite() {
    map_.reset();
    log_.reset();
  }
  static std::unique_ptr<ArgoverseLog> log_;
  static std::unique_ptr<HdMap> map_;
};
std::unique_ptr<ArgoverseLog> SessionTest::log_;
std::unique_ptr<HdMap> SessionTest::map_;

// Repeated runs are compared: no wall-clock match budget (under load it rejects matches at random).
Config untimed() {
  Config config;
  config.match.timeBudgetMs = 1e6;
  return config;
}

void expectSameTrajectory(const PoseTrajectory& a, const PoseTrajectory& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(a.poses()[i].matrix() == b.poses()[i].matrix()) << "pose " << i;
}

TEST_F(SessionTest, SteppingCancellingAndResumingEqualsOneRun) {
  Session whole(*log_, map_.get(), untimed());
  size_t calls = 0;
  ASSERT_TRUE(whole.run([&](size_t done, size_t total) { EXPECT_EQ(done, ++calls); EXPECT_EQ(total, log_->sweepCount()); }));
  EXPECT_TRUE(whole.done());
  whole.optimize();

  Session parts(*log_, map_.get(), untimed());
  parts.stepKeyframe();
  parts.stepKeyframe();
  const size_t afterTwo = parts.sweepsDone();
  EXPECT_EQ(parts.odometry().keyframes().size(), 2u);
  EXPECT_EQ(parts.matches().size(), 2u);
  EXPECT_EQ(parts.odometry().keyframes().back().frame, afterTwo - 1);
  std::atomic<bool> cancel{false};
  const bool finished = parts.run([&](size_t done, size_t) { if (done == afterTwo + 5) cancel = true; }, &cancel);
  EXPECT_FALSE(finished);
  EXPECT_EQ(parts.sweepsDone(), afterTwo + 5);
  ASSERT_TRUE(parts.run());
  parts.optimize();

  expectSameTrajectory(whole.odometryTrajectory(), parts.odometryTrajectory());
  expectSameTrajectory(whole.optimizedTrajectory(), parts.optimizedTrajectory());
  ASSERT_EQ(whole.matches().size(), parts.matches().size());
  EXPECT_GT(whole.matches().size(), 5u);
}

TEST_F(SessionTest, FinishGivesWhatRunPipelineGives) {
  Session session(*log_, map_.get(), untimed());
  session.run();
  const PipelineRun run = session.finish(0.2);
  const PipelineRun direct = runPipeline(*log_, untimed());
  expectSameTrajectory(run.optimized, direct.optimized);
  EXPECT_EQ(run.mapPoints.size(), direct.mapPoints.size());
  EXPECT_EQ(run.odometry->keyframes().size(), direct.odometry->keyframes().size());
}

TEST_F(SessionTest, InspectingAKeyframeReproducesItsMatchAndLabelsItsSubmap) {
  Session session(*log_, map_.get(), untimed());
  session.run();
  const Config config = untimed();
  for (size_t k : {size_t(1), session.matches().size() - 1}) {
    const KeyframeInspection in = session.inspectKeyframe(k, config.roadPoints, config.match);
    const KeyframeMatch& run = session.matches()[k];
    EXPECT_EQ(in.frame, run.frame);
    EXPECT_EQ(in.start, planarPose(run.predicted));
    EXPECT_EQ(in.match.estimate, run.match.estimate) << "keyframe " << k;
    EXPECT_EQ(in.match.status, run.match.status);
    ASSERT_EQ(in.points.size(), in.labels.size());
    size_t road = 0, ground = 0;
    for (SubmapLabel l : in.labels) {
      road += l == SubmapLabel::Road || l == SubmapLabel::Curb;
      ground += l == SubmapLabel::Ground;
    }
    EXPECT_GT(road, in.roadPoints.size());  // thinned
    EXPECT_GT(ground, 0u);
    EXPECT_TRUE(in.truth.has_value());
  }
  // Other options change the match; a start offset moves the start.
  MatchOptions coarse = config.match;
  coarse.cellSizes = {1.0};
  coarse.maxIterations = 1;
  const Eigen::Vector3d start = planarPose(session.matches()[1].predicted) + Eigen::Vector3d(0.5, -0.3, 0.0);
  const KeyframeInspection moved = session.inspectKeyframe(1, config.roadPoints, coarse, start);
  EXPECT_EQ(moved.start, start);
  EXPECT_NE(moved.match.estimate, session.matches()[1].match.estimate);
  EXPECT_THROW(session.inspectKeyframe(session.matches().size(), config.roadPoints, config.match), Error);
}

TEST_F(SessionTest, ReoptimisingWithOtherOptionsChangesTheTrajectoryAndIsRepeatable) {
  Session session(*log_, map_.get(), untimed());
  session.run();
  session.optimize();
  const PoseTrajectory before = session.optimizedTrajectory();
  // Priors 0.3 m higher (another ego height above the ground): the optimised trajectory rises
  // towards them (the odometry's own drift model is the one the priors made likeliest, whatever
  // per-metre sigmas are passed, so it is the priors that change here).
  PosePriorOptions higher = session.config().prior;
  higher.egoHeight += 0.3;
  const SolveSummary s = session.optimize(higher, session.config().graph);
  EXPECT_GT(s.iterations, 0);
  const PoseTrajectory after = session.optimizedTrajectory();
  ASSERT_EQ(after.size(), before.size());
  double moved = 0;
  for (size_t i = 0; i < after.size(); ++i)
    moved = std::max(moved, (after.poses()[i].translation() - before.poses()[i].translation()).norm());
  EXPECT_GT(moved, 1e-3);
  // Back to the original options: the original result again (a rebuilt graph, warm-started elsewhere).
  session.optimize(untimed().prior, untimed().graph);
  const PoseTrajectory back = session.optimizedTrajectory();
  for (size_t i = 0; i < back.size(); ++i)
    EXPECT_LT((back.poses()[i].translation() - before.poses()[i].translation()).norm(), 2e-3) << "pose " << i;
}

TEST_F(SessionTest, WithoutAMapItIsOdometryAlone) {
  Session session(*log_, nullptr, untimed());
  EXPECT_FALSE(session.hasPriors());
  session.run();
  EXPECT_TRUE(session.matches().empty());
  EXPECT_TRUE(session.optimizedTrajectory().empty());
  EXPECT_EQ(session.keyframePoses().size(), session.odometry().keyframes().size());
  EXPECT_THROW(session.inspectKeyframe(0, untimed().roadPoints, untimed().match), Error);
}

}  // namespace hdprior
