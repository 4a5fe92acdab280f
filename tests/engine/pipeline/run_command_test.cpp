#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "engine/io/lidar_sweep.h"
#include "engine/io/tum_trajectory.h"
#include "run_output.h"
#include "test_data.h"

namespace hdprior {
namespace fs = std::filesystem;

namespace {

// A copy of the shared log's metadata (symlinks) with the given sweeps folder content.
fs::path logWithoutSweeps(const std::string& name) {
  const fs::path src = test::sharedLog();
  const fs::path dir = test::freshOutputDir(name) / src.filename();
  fs::create_directories(dir / "sensors" / "lidar");
  for (const char* entry : {"calibration", "map", "city_SE3_egovehicle.feather"}) fs::create_directory_symlink(src / entry, dir / entry);
  return dir;
}

using test::oneLine;

}  // namespace

TEST(RunCommand, RealLogWritesEveryOutput) {
  const fs::path out = test::freshOutputDir("run_real");
  const auto r = test::runHdprior("run " + test::sharedLog().string() + " --out " + out.string() + " --no-prior");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("2 sweeps"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("2/2 sweeps"), std::string::npos);
  for (const char* f : {"groundtruth.tum", "odometry.tum", "keyframes.json", "metrics.json", "map.ply"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  EXPECT_EQ(readTum(out / "odometry.tum").size(), 2u);
  std::ifstream in(out / "metrics.json");
  const auto m = nlohmann::json::parse(in);
  EXPECT_EQ(m["sweeps"], 2);
  EXPECT_LT(m["odometry"]["ate_translation_m"]["max"].get<double>(), 0.05);
  EXPECT_EQ(m["odometry"]["alignment"], "none (city frame; runs start at the first ground-truth pose)");
  for (const auto& entry : fs::directory_iterator(out)) EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos);
}

TEST(RunCommand, RealLogWithPriorsWritesTheOptimizedTrajectory) {
  const fs::path out = test::freshOutputDir("run_prior");
  const auto r = test::runHdprior("run " + test::sharedLog().string() + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("optimized ATE rmse"), std::string::npos) << r.out;
  EXPECT_EQ(readTum(out / "optimized.tum").size(), 2u);
  std::ifstream in(out / "metrics.json");
  const auto m = nlohmann::json::parse(in);
  EXPECT_TRUE(m["priors"].get<bool>());
  const auto& matches = m["matches"];
  EXPECT_EQ(matches["accepted"].get<int>() + matches["degenerate"].get<int>() + matches["rejected"].get<int>(),
            m["keyframes"].get<int>());
  // The shared real sweep matches within half a metre of the ground truth (the matches' along-road offset there: docs/experiments/2026-11-22-pose-graph-and-ndt-bias.md).
  EXPECT_LT(m["optimized"]["ate_translation_m"]["max"].get<double>(), 0.5);
  for (const char* direction : {"along_m", "lateral_m", "yaw_deg"}) {
    EXPECT_TRUE(m["prior_calibration"][direction].contains("share_beyond_3_sigma")) << direction;
  }
  for (const char* stage : {"odometry_s", "road_points_s", "match_s", "graph_s", "pipeline_s"}) {
    EXPECT_GT(m["timing"][stage].get<double>(), 0.0) << stage;
  }
  std::ifstream kin(out / "keyframes.json");
  const auto k = nlohmann::json::parse(kin);
  EXPECT_TRUE(k[0].contains("match"));
  EXPECT_TRUE(k[0].contains("optimized_city_T_ego"));
}

TEST(RunCommand, LogWithoutSweepsIsOneLineExit2) {
  const fs::path log = logWithoutSweeps("run_nosweeps");
  const fs::path out = log.parent_path() / "out";
  const auto r = test::runHdprior("run " + log.string() + " --out " + out.string() + " --no-prior");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(oneLine(r.err), r.err);
  EXPECT_NE(r.err.find("no sweeps"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(RunCommand, ZeroPointSweepIsOneLineExit2) {
  const fs::path log = logWithoutSweeps("run_emptysweep");
  const fs::path src = test::sharedLog() / "sensors" / "lidar";
  for (const auto& e : fs::directory_iterator(src)) fs::copy_file(e.path(), log / "sensors" / "lidar" / e.path().filename());
  LidarSweep empty;
  empty.timestampNs = 315966265460032000;
  writeLidarSweep(log / "sensors" / "lidar" / "315966265460032000.feather", empty);
  const fs::path out = log.parent_path() / "out";
  const auto r = test::runHdprior("run " + log.string() + " --out " + out.string() + " --no-prior");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("315966265460032000.feather: the sweep has zero points"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(RunCommand, BadConfigIsOneLineExit2) {
  const fs::path dir = test::freshOutputDir("run_badconfig");
  std::ofstream(dir / "unknown.json") << R"({"odometry": {"registration": {"huber": 0.1}}})";
  std::ofstream(dir / "negative.json") << R"({"keyframes": {"rotation_deg": -5}})";
  auto r = test::runHdprior("run " + test::sharedLog().string() + " --out " + (dir / "o").string() + " --no-prior --config " + (dir / "unknown.json").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("unknown.json: unknown key odometry.registration.huber"), std::string::npos) << r.err;
  r = test::runHdprior("run " + test::sharedLog().string() + " --out " + (dir / "o").string() + " --no-prior --config " + (dir / "negative.json").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("negative.json: keyframes.rotation_deg = -5 is out of range"), std::string::npos) << r.err;
  EXPECT_EQ(oneLine(r.err), r.err);
  EXPECT_FALSE(fs::exists(dir / "o"));
}

}  // namespace hdprior
