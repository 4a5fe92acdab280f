#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "engine/eval/trajectory_errors.h"
#include "engine/graph/pose_graph.h"
#include "engine/io/tum_trajectory.h"
#include "engine/odom/odometry_drift.h"
#include "run_output.h"
#include "test_data.h"

namespace hdprior {
namespace fs = std::filesystem;

namespace {

using test::metricsOf;
using test::oneLine;

}  // namespace

// `hdprior run LOG --odometry-drift S,Y` on a short, straight simulated town drive (town 1 runs
// straight through its junctions; 6 s, ~45 m: RPE over 10 m; the 100 m figure is checked
// analytically in OdometryDrift.RelativePoseErrorOfAStraightDriveShowsTheDrift). Runs are compared
// bit for bit: no wall-clock match budget (under load it would reject matches at random).
class OdometryDriftRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const test::SimulatedDrive drive = test::simulatedTownDrive("drift_run", 1, 0, 6.0);
    log_ = new fs::path(drive.log);
    config_ = new fs::path(drive.folder / "untimed.json");
    std::ofstream(*config_) << R"({"match": {"time_budget_ms": 1000000}})";
  }
  static void TearDownTestSuite() {
    delete log_;
    delete config_;
    log_ = config_ = nullptr;
  }
  static test::CommandResult run(const fs::path& out, const std::string& options) {
    return test::runHdprior("run " + log_->string() + " --out " + out.string() + " --config " + config_->string() + " " + options);
  }
  static fs::path* log_;
  static fs::path* config_;
};
fs::path* OdometryDriftRun::log_ = nullptr;
fs::path* OdometryDriftRun::config_ = nullptr;

TEST(OdometryDriftOption, BadValuesAreOneLineExit2AndWriteNothing) {
  const fs::path dir = test::freshOutputDir("drift_bad");
  const std::string log = test::sharedLog().string();
  const struct {
    const char* value;
    const char* message;
  } cases[] = {{"0.2,0.5", "option --odometry-drift: scale = 0.2 is out of range (-0.2, 0.2)"},
               {"0.007,-25", "option --odometry-drift: yaw_deg_per_100m = -25 is out of range [-20, 20]"},
               {"0.007", "option --odometry-drift: '0.007' is not SCALE,YAW_DEG_PER_100M"},
               {"0.007,half", "option --odometry-drift: 'half' is not a number"}};
  for (const auto& c : cases) {
    for (const std::string& command : {"run " + log, "eval " + test::sharedDataDir().string()}) {
      const auto r = test::runHdprior(command + " --out " + (dir / "o").string() + " --no-prior --odometry-drift " + c.value);
      EXPECT_EQ(r.status, 2) << command << " " << c.value;
      EXPECT_EQ(oneLine(r.err), r.err) << r.err;
      EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
      EXPECT_FALSE(fs::exists(dir / "o")) << command << " " << c.value;
    }
  }
  const auto r = test::runHdprior("run " + log + " --out " + (dir / "o").string() + " --no-prior --odometry-drift");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("option --odometry-drift: needs a value"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "o"));
}

// The drifted odometry against ground truth looks like the ground truth degraded by the same drift
// (the odometry's own error is two orders smaller), and two runs are identical.
TEST_F(OdometryDriftRun, DriftedOdometryShowsTheDriftAndIsDeterministic) {
  const fs::path dir = test::freshOutputDir("drift_run_odometry");
  for (const char* name : {"a", "b"}) {
    const auto r = run(dir / name, "--no-prior --odometry-drift 0.007,0.5");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("injected odometry drift: scale 0.007, yaw 0.5 deg/100 m"), std::string::npos) << r.out;
  }
  EXPECT_EQ(test::readFileText(dir / "a" / "odometry.tum"), test::readFileText(dir / "b" / "odometry.tum"));

  const auto m = metricsOf(dir / "a");
  EXPECT_EQ(m["odometry_drift"]["scale"].get<double>(), 0.007);
  EXPECT_EQ(m["odometry_drift"]["yaw_deg_per_100m"].get<double>(), 0.5);
  EXPECT_EQ(m["odometry_drift"]["pitch_deg_per_100m"].get<double>(), 0.0);
  const auto& odometry = m["odometry"];
  ASSERT_GT(odometry["rpe_10m"]["segments"].get<int>(), 20) << odometry;

  const PoseTrajectory gt = readTum(dir / "a" / "groundtruth.tum");
  const TrajectoryEvaluation expected =
      evaluateTrajectory(gt, PoseTrajectory(gt.timestamps(), driftedPoses(gt.poses(), {0.007, 0.5, 0.0})), AlignmentMode::None);
  const double rpe10 = odometry["rpe_10m"]["translation_percent"].get<double>();
  const double ate = odometry["ate_translation_m"]["rmse"].get<double>();
  std::printf("drifted odometry: RPE10 %.3f %% (ground truth drifted: %.3f %%), yaw %.3f deg/100 m; ATE rmse %.3f m (%.3f m)\n",
              rpe10, expected.rpe10.translationPercent, odometry["rpe_10m"]["yaw_deg_per_100m"].get<double>(), ate,
              expected.ate.translation.rmse);
  // Scale and a little of the yaw; a segment overshoots 10 m by up to one 0.8 m step (RPE divides by 10 m).
  EXPECT_GT(expected.rpe10.translationPercent, 0.69);
  EXPECT_LT(expected.rpe10.translationPercent, 0.78);
  EXPECT_NEAR(rpe10, expected.rpe10.translationPercent, 0.1);   // the odometry's own: ~0.03 %
  EXPECT_NEAR(odometry["rpe_10m"]["yaw_deg_per_100m"].get<double>(), 0.5, 0.2);
  EXPECT_GT(expected.ate.translation.rmse, 0.1);
  EXPECT_NEAR(ate, expected.ate.translation.rmse, 0.03 + 0.1 * expected.ate.translation.rmse);
}

// --odometry-drift 0,0 is no drift at all: the plain run with priors, bit for bit.
TEST_F(OdometryDriftRun, ZeroDriftIsThePlainRunBitForBit) {
  const fs::path dir = test::freshOutputDir("drift_run_zero");
  ASSERT_EQ(run(dir / "plain", "").status, 0);
  const auto r = run(dir / "zero", "--odometry-drift 0,0,0");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("injected"), std::string::npos) << r.out;
  for (const char* f : {"odometry.tum", "optimized.tum"}) {
    EXPECT_EQ(test::readFileText(dir / "plain" / f), test::readFileText(dir / "zero" / f)) << f;
  }
  const auto plain = metricsOf(dir / "plain"), zero = metricsOf(dir / "zero");
  EXPECT_EQ(plain["optimized"], zero["optimized"]);
  EXPECT_EQ(plain["odometry_drift"], zero["odometry_drift"]);
  EXPECT_EQ(plain["odometry_drift_model"], zero["odometry_drift_model"]);
  EXPECT_EQ(zero["odometry_drift"]["scale"].get<double>(), 0.0);
}

// With priors, the injected drift is not told to the graph: its drift model is the configured one
// times the factor the priors made likeliest, and the priors take out the lateral part of the drift
// (along a straight road they cannot see the scale error: docs/method.md).
TEST_F(OdometryDriftRun, PriorsCorrectTheInjectedDrift) {
  const fs::path out = test::freshOutputDir("drift_run_priors");
  const auto r = run(out, "--odometry-drift 0.007,0.5");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto m = metricsOf(out);
  // metrics.json shows the evidence for the pick: every candidate's log-likelihood, and the pick is
  // the tightest candidate within the margin of the likeliest.
  const auto& model = m["odometry_drift_model"];
  ASSERT_EQ(model["candidates"].size(), 42u) << model;
  double best = -1e300;
  for (const auto& c : model["candidates"]) best = std::max(best, c["log_likelihood"].get<double>());
  const double margin = model["margin_nats"].get<double>();
  double tightest = 1e300, chosen = 0.0;
  for (const auto& c : model["candidates"]) {
    if (c["log_likelihood"].get<double>() >= best - margin) tightest = std::min(tightest, c["factor"].get<double>());
    if (c["chosen"].get<bool>()) chosen = c["factor"].get<double>();
  }
  EXPECT_EQ(chosen, tightest) << model;
  EXPECT_DOUBLE_EQ(model["translation_sigma_per_m"].get<double>(), PoseGraphOptions{}.odometryTranslationSigmaPerM * chosen);
  EXPECT_DOUBLE_EQ(model["rotation_sigma_deg_per_m"].get<double>(), PoseGraphOptions{}.odometryRotationSigmaDegPerM * chosen);
  const double odometry = m["odometry"]["ate_translation_m"]["rmse"].get<double>();
  const double optimized = m["optimized"]["ate_translation_m"]["rmse"].get<double>();
  std::printf("ATE rmse: drifted odometry %.3f m, optimized %.3f m; lateral %.3f -> %.3f m\n", odometry, optimized,
              m["odometry"]["ate_lateral_m"]["rmse"].get<double>(), m["optimized"]["ate_lateral_m"]["rmse"].get<double>());
  EXPECT_LT(optimized, odometry);
  // The drift here is mostly along the road; the honest priors (sigma >= 0.2 m, the map's own error)
  // cannot sharpen the odometry's 2 cm lateral error on this 6 s drive, and must not spoil it.
  EXPECT_LT(m["optimized"]["ate_lateral_m"]["rmse"].get<double>(), 0.05);
}

}  // namespace hdprior
