#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "engine/io/argoverse_log.h"
#include "test_data.h"
#include "ui/ate_series.h"
#include "ui/odometry_file.h"
#include "ui/tuning_bench.h"

namespace hdprior::test {
namespace {
namespace fs = std::filesystem;

double maxDistance(const PoseTrajectory& a, const PoseTrajectory& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
    d = std::max(d, (a.poses()[i].translation() - b.poses()[i].translation()).norm());
  return d;
}

std::vector<std::string> labels(const render::Analysis& analysis) {
  std::vector<std::string> out;
  for (const ui::AteSeries& s : ui::ateSeries(analysis)) out.push_back(s.label);
  return out;
}

// The file's poses land where a run over it puts them: `first` anchors them at the first true
// pose, `city` takes them as they are.
TEST(OdometryFile, PlacesTheFileAsARunOverItWould) {
  const ArgoverseLog log(sharedLog());
  const fs::path dir = freshOutputDir("ui_odometry_file_frames");
  ui::OdometryFile file;
  file.path = writeMovedTruth(sharedLog(), dir / "shifted.tum", 100.0, 50.0, 0.0).string();
  ASSERT_TRUE(file.open(log)) << file.error();
  EXPECT_EQ(file.format, ui::OdometryFile::Format::Tum);  // detected from .tum
  EXPECT_LT(maxDistance(file.cityTrajectory(), log.cityTEgoAtSweeps()), 1e-5);

  file.frame = GivenOdometryFrame::City;
  ASSERT_TRUE(file.open(log)) << file.error();
  EXPECT_NEAR(maxDistance(file.cityTrajectory(), log.cityTEgoAtSweeps()), std::hypot(100.0, 50.0), 1e-5);
  ASSERT_TRUE(file.forRun().has_value());
  file.use = false;
  EXPECT_FALSE(file.forRun().has_value());
}

// A bad file is one line naming the file and the line, and leaves no file open.
TEST(OdometryFile, ABadFileIsOneLineNamingTheFileAndTheLine) {
  const ArgoverseLog log(sharedLog());
  const fs::path dir = freshOutputDir("ui_odometry_file_bad");
  ui::OdometryFile file;
  file.path = writeMovedTruth(sharedLog(), dir / "good.tum", 0.0, 0.0, 0.0).string();
  ASSERT_TRUE(file.open(log));
  std::ofstream(dir / "bad.tum") << "# header\n315966265.2 1 2 3\n";
  file.path = (dir / "bad.tum").string();
  EXPECT_FALSE(file.open(log));
  EXPECT_FALSE(file.isOpen());
  EXPECT_TRUE(file.cityTrajectory().empty());
  EXPECT_NE(file.error().find("bad.tum"), std::string::npos) << file.error();
  EXPECT_NE(file.error().find("bad.tum:2: expected 8 fields"), std::string::npos) << file.error();
  EXPECT_EQ(file.error().find('\n'), std::string::npos) << file.error();

  std::ofstream(dir / "early.tum") << "1.0 0 0 0 0 0 0 1\n2.0 1 0 0 0 0 0 1\n";  // long before the log
  file.path = (dir / "early.tum").string();
  EXPECT_FALSE(file.open(log));
  EXPECT_NE(file.error().find("must cover every sweep"), std::string::npos) << file.error();

  file.path = (dir / "none.tum").string();
  EXPECT_FALSE(file.open(log));
  EXPECT_NE(file.error().find("none.tum"), std::string::npos) << file.error();
}

// The Pipeline tab's run over an opened file is `run --odometry`: the session takes the file as its
// odometry, and the plot shows the file's error as the odometry's beside the optimised one; with
// the checkbox off the run is the built-in odometry's and the file is its own line.
TEST(OdometryFile, TheBenchRunsThePipelineOverTheOpenedFile) {
  const ArgoverseLog log(sharedLog());
  const fs::path dir = freshOutputDir("ui_odometry_file_bench");
  ui::TuningBench bench(log, Config{});
  bench.odometryFile.path = writeMovedTruth(sharedLog(), dir / "given.tum", 0.3, -0.2, 0.0).string();
  bench.odometryFile.frame = GivenOdometryFrame::City;
  ASSERT_TRUE(bench.openOdometryFile()) << bench.odometryFile.error();
  EXPECT_TRUE(bench.poll());
  const render::Analysis& a = bench.analysis();
  ASSERT_EQ(a.file.size(), log.sweepCount());
  for (double e : a.fileError) EXPECT_NEAR(e, std::hypot(0.3, 0.2), 1e-5);
  EXPECT_EQ(labels(a), std::vector<std::string>{"file given.tum"});

  bench.run();
  bench.runner().wait();
  bench.poll();
  ASSERT_TRUE(bench.runner().error().empty()) << bench.runner().error();
  const Session* session = bench.runner().session();
  ASSERT_NE(session, nullptr);
  ASSERT_TRUE(session->givenOdometry().has_value());
  EXPECT_EQ(session->givenOdometry()->file, bench.odometryFile.path);
  EXPECT_EQ(ui::odometrySourceText(*session), "file " + bench.odometryFile.path + " (tum, frame city)");
  EXPECT_EQ(a.odometryFile, bench.odometryFile.path);
  EXPECT_LT(maxDistance(a.odometry, a.file), 1e-6);  // the run's odometry is the file
  EXPECT_FALSE(a.optimized.empty());
  EXPECT_EQ(labels(a), (std::vector<std::string>{"odometry (file given.tum)", "optimised"}));
  EXPECT_EQ(ui::ateSeries(a)[0].kind, ui::AteSeries::Kind::File);  // drawn in the file's colour

  bench.odometryFile.use = false;
  bench.run();
  bench.runner().wait();
  bench.poll();
  ASSERT_NE(bench.runner().session(), nullptr);
  EXPECT_FALSE(bench.runner().session()->givenOdometry().has_value());
  EXPECT_EQ(labels(a), (std::vector<std::string>{"file given.tum", "odometry (built-in)", "optimised"}));

  bench.closeOdometryFile();
  bench.poll();
  EXPECT_TRUE(a.file.empty());
  EXPECT_EQ(labels(a), (std::vector<std::string>{"odometry (built-in)", "optimised"}));
}

TEST(AteSeries, NothingComputedIsNoLine) { EXPECT_TRUE(ui::ateSeries(render::Analysis{}).empty()); }

}  // namespace
}  // namespace hdprior::test
