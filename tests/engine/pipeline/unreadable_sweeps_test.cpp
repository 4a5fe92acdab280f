// One bad sweep does not cost the log: it is skipped with one warning naming it, the odometry bridges
// the gap, metrics.json and eval's per_log.csv count it; more than sweeps.max_unreadable_share of
// them fails the log with one line naming the share.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/tum_trajectory.h"
#include "engine/map/hd_map.h"
#include "engine/odom/given_odometry.h"
#include "engine/pipeline/session.h"
#include "test_data.h"

namespace hdprior {
namespace fs = std::filesystem;

class UnreadableSweeps : public ::testing::Test {
 protected:
  // A 6 s town drive (60 sweeps), simulated once per test process.
  static void SetUpTestSuite() {
    source_ = new fs::path(test::simulatedTownDrive("unreadable", 2, 3, 6.0).log);
  }
  static void TearDownTestSuite() { delete source_; }

  // A copy of the drive whose sweeps `bad` are cut to half their length.
  static fs::path copyWithTruncatedSweeps(const std::string& name, const std::vector<size_t>& bad) {
    const fs::path dir = test::freshOutputDir(name) / source_->filename();
    fs::copy(*source_, dir, fs::copy_options::recursive);
    const ArgoverseLog log(dir);
    for (size_t i : bad) fs::resize_file(log.sweepPath(i), fs::file_size(log.sweepPath(i)) / 2);
    return dir;
  }
  static std::string sweepName(size_t i) {
    const ArgoverseLog log(*source_);
    return log.sweepPath(i).filename().string();
  }
  static nlohmann::json metrics(const fs::path& out) {
    std::ifstream in(out / "metrics.json");
    return nlohmann::json::parse(in);
  }
  static fs::path* source_;
};
fs::path* UnreadableSweeps::source_ = nullptr;

namespace {

size_t lineCount(const std::string& s) { return size_t(std::count(s.begin(), s.end(), '\n')); }

std::vector<std::string> linesStartingWith(const std::string& text, const std::string& prefix) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) out.push_back(line);
  return out;
}

}  // namespace

TEST_F(UnreadableSweeps, ATruncatedSweepIsSkippedCountedAndBridged) {
  const fs::path log = copyWithTruncatedSweeps("unreadable_one", {30});
  const fs::path intactOut = log.parent_path() / "intact", out = log.parent_path() / "out";
  const auto intact = test::runHdprior("run " + source_->string() + " --out " + intactOut.string());
  ASSERT_EQ(intact.status, 0) << intact.err;
  const auto r = test::runHdprior("run " + log.string() + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  // One warning line, naming the file and the problem.
  const auto warnings = linesStartingWith(r.err, "hdprior run: warning: skipped ");
  ASSERT_EQ(warnings.size(), 1u) << r.err;
  EXPECT_NE(warnings[0].find(sweepName(30) + ": "), std::string::npos) << warnings[0];
  EXPECT_NE(r.out.find("59 sweeps (1 unreadable skipped)"), std::string::npos) << r.out;

  const auto m = metrics(out), m0 = metrics(intactOut);
  EXPECT_EQ(m["sweeps"], 59);
  EXPECT_EQ(m["skipped_sweeps"]["count"], 1);
  EXPECT_EQ(m["skipped_sweeps"]["files"], nlohmann::json::array({sweepName(30)}));
  EXPECT_EQ(m0["skipped_sweeps"]["count"], 0);
  // The skipped sweep has no pose; the ATE stays what it is with every sweep.
  const PoseTrajectory odometry = readTum(out / "odometry.tum");
  EXPECT_EQ(odometry.size(), 59u);
  const ArgoverseLog shared(log);
  for (int64_t t : odometry.timestamps()) EXPECT_NE(t, shared.sweepTimestamps()[30]);
  for (const char* trajectory : {"odometry", "optimized"}) {
    const double rmse = m[trajectory]["ate_translation_m"]["rmse"], rmse0 = m0[trajectory]["ate_translation_m"]["rmse"];
    std::printf("[ info ] %s ATE rmse %.4f m with sweep 30 skipped, %.4f m with every sweep\n", trajectory, rmse, rmse0);
    EXPECT_LT(rmse, rmse0 + 0.02) << trajectory;
    EXPECT_LT(double(m[trajectory]["ate_translation_m"]["max"]), 0.2) << trajectory;
  }
  // keyframes.json numbers frames as the log does.
  std::ifstream kin(out / "keyframes.json");
  for (const auto& k : nlohmann::json::parse(kin)) {
    EXPECT_EQ(k["timestamp_ns"].get<int64_t>(), shared.sweepTimestamps()[k["frame"].get<size_t>()]);
  }
}

TEST_F(UnreadableSweeps, MoreThanTheShareFailsTheLogWithOneLineNamingIt) {
  const fs::path log = copyWithTruncatedSweeps("unreadable_many", {10, 20, 30, 40});  // 4 of 60: 6.7 %
  const fs::path out = log.parent_path() / "out";
  const auto r = test::runHdprior("run " + log.string() + " --out " + out.string() + " --no-prior");
  EXPECT_EQ(r.status, 2);
  // One error line after the progress lines ("run: 10 % ..." when stderr is not a terminal).
  EXPECT_EQ(linesStartingWith(r.err, "hdprior run: ").size(), 1u) << r.err;
  EXPECT_EQ(lineCount(r.err), 1u + linesStartingWith(r.err, "run: ").size()) << r.err;
  EXPECT_NE(r.err.find(sweepName(40) + ": "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("4 of the log's 60 sweeps (6.7 %) are unreadable, more than 5 % (config sweeps.max_unreadable_share)"),
            std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // A larger share allowed in the configuration: mapped, all four counted.
  std::ofstream(log.parent_path() / "lenient.json") << R"({"sweeps": {"max_unreadable_share": 0.1}})";
  const auto lenient = test::runHdprior("run " + log.string() + " --out " + out.string() + " --no-prior --config " +
                                        (log.parent_path() / "lenient.json").string());
  ASSERT_EQ(lenient.status, 0) << lenient.err;
  EXPECT_EQ(linesStartingWith(lenient.err, "hdprior run: warning: skipped ").size(), 4u) << lenient.err;
  EXPECT_EQ(metrics(out)["skipped_sweeps"]["count"], 4);
}

TEST_F(UnreadableSweeps, EvalCountsTheSkippedSweepsOfEachLog) {
  const fs::path log = copyWithTruncatedSweeps("unreadable_eval", {30});
  const fs::path out = log.parent_path().parent_path() / "eval_out";
  const auto r = test::runHdprior("eval " + log.parent_path().string() + " --out " + out.string() + " --no-prior -j 1");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto warnings = linesStartingWith(r.err, "hdprior eval: log " + log.filename().string() + ": warning: skipped ");
  ASSERT_EQ(warnings.size(), 1u) << r.err;
  EXPECT_NE(warnings[0].find(sweepName(30)), std::string::npos);
  std::istringstream csv(test::readFileText(out / "per_log.csv"));
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_EQ(header.rfind("log_id,path,sweeps,skipped_sweeps,", 0), 0u) << header;
  EXPECT_NE(row.find("," + log.string() + ",59,1,"), std::string::npos) << row;
}

// The app's path: a Session steps over the bad sweep and numbers frames as the log does.
TEST_F(UnreadableSweeps, ASessionStepsOverTheBadSweep) {
  const fs::path dir = copyWithTruncatedSweeps("unreadable_session", {0, 30});
  const ArgoverseLog log(dir);
  Config config;
  config.match.timeBudgetMs = 1e6;
  config.maxUnreadableSweepShare = 0.05;
  const std::unique_ptr<HdMap> map = loadPriorMap(log, config);
  Session session(log, map.get(), config);
  ASSERT_TRUE(session.run());
  EXPECT_EQ(session.sweepsDone(), 60u);
  ASSERT_EQ(session.skippedSweeps().size(), 2u);
  EXPECT_EQ(session.skippedSweeps()[1].index, 30u);
  EXPECT_EQ(session.skippedSweeps()[1].file, log.sweepPath(30));
  EXPECT_FALSE(session.skippedSweeps()[1].problem.empty());
  const PoseTrajectory odometry = session.odometryTrajectory();
  ASSERT_EQ(odometry.size(), 58u);
  // The first sweep unreadable: the run starts from the second one's ground-truth pose.
  EXPECT_EQ(odometry.timestamps().front(), log.sweepTimestamps()[1]);
  EXPECT_LT((odometry.poses().front().translation() - log.cityTEgo().at(log.sweepTimestamps()[1]).translation()).norm(), 1e-9);
  EXPECT_EQ(session.sweepOfFrame(28), 29u);
  EXPECT_EQ(session.sweepOfFrame(29), 31u);
  const auto& keyframes = session.odometry().keyframes();
  const size_t last = keyframes.size() - 1;
  const KeyframeInspection in = session.inspectKeyframe(last, config.roadPoints, config.match);
  EXPECT_EQ(log.sweepTimestamps()[in.frame], keyframes[last].timestampNs);
  session.optimize();
  EXPECT_EQ(session.optimizedTrajectory().size(), 58u);
  const PipelineRun run = session.finish(0.2);
  EXPECT_EQ(run.skippedSweeps.size(), 2u);
  EXPECT_GT(run.mapPoints.size(), 1000u);
}

// With a given trajectory the odometry frame stays the first sweep's (the file covers it even when
// the sweep file is broken): here the ground truth, given in the city frame, comes out unchanged.
TEST_F(UnreadableSweeps, AGivenTrajectoryIsUnmovedByAnUnreadableFirstSweep) {
  const fs::path dir = copyWithTruncatedSweeps("unreadable_given", {0, 30});
  const ArgoverseLog log(dir);
  GivenOdometry given;
  std::vector<SE3> poses;
  for (int64_t t : log.sweepTimestamps()) poses.push_back(log.cityTEgo().at(t));
  given.trajectory = PoseTrajectory(log.sweepTimestamps(), poses, "ground truth");
  given.frame = GivenOdometryFrame::City;
  given.file = "ground truth";
  Session session(log, nullptr, Config{}, {.priors = false, .givenOdometry = given});
  ASSERT_TRUE(session.run());
  EXPECT_EQ(session.skippedSweeps().size(), 2u);
  const PoseTrajectory odometry = session.odometryTrajectory();
  ASSERT_EQ(odometry.size(), 58u);
  for (size_t i = 0; i < odometry.size(); ++i) {
    const int64_t t = odometry.timestamps()[i];
    EXPECT_LT((odometry.poses()[i].translation() - log.cityTEgo().at(t).translation()).norm(), 1e-6) << "pose " << i;
  }
}

}  // namespace hdprior
