#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>

#include "bad_input.h"
#include "render/image_compare.h"
#include "test_data.h"

namespace hdprior::test {
namespace {
namespace fs = std::filesystem;

// The command draws the same picture as the library (it is the same renderer).
TEST(SnapshotCommand, WritesThePngOfTheGolden) {
  const fs::path dir = freshOutputDir("snapshot_command");
  const fs::path out = dir / "frame0.png";
  const CommandResult r =
      runHdprior("snapshot " + quoted(sharedLog()) + " --frame 0 --size 640x360 --view top --out " + quoted(out));
  ASSERT_EQ(r.status, 0) << r.err;
  const render::Image image = readPng(out);
  EXPECT_EQ(image.width, 640);
  EXPECT_EQ(image.height, 360);
  EXPECT_EQ(checkGolden(image, "frame0_top_all"), "");
}

// The first real sweep's ground segmentation against its real labels (is_ground_0): agreeing
// ground green, ground the labels deny red, labelled ground missed amber, the rest grey.
TEST(SnapshotCommand, ColoursTheGroundSegmentationAgainstRealLabels) {
  const fs::path dir = freshOutputDir("snapshot_command_ground_labels");
  const fs::path labels = sharedDataDir() / "labels/7fab2350-7eaf-3b7e-a39d-6937a4c1bede/flow_labels.feather";
  const fs::path out = dir / "labels.png";
  const CommandResult r = runHdprior("snapshot " + quoted(sharedLog()) + " --frame 0 --size 640x360 --view orbit --ground-labels " +
                                     quoted(labels) + " --out " + quoted(out));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(checkGolden(readPng(out), "real_ground_labels_orbit"), "");
  // The labels are of sweep 0 alone: another sweep's point count is named, and nothing is written.
  const fs::path other = dir / "other.png";
  EXPECT_TRUE(failedWithOneLine(runHdprior("snapshot " + quoted(sharedLog()) + " --frame 1 --ground-labels " + quoted(labels) +
                                           " --out " + quoted(other)),
                                labels.string() + ": has 99229 rows, the sweep 99466 points"));
  EXPECT_FALSE(fs::exists(other));
  EXPECT_TRUE(failedWithOneLine(runHdprior("snapshot " + quoted(sharedLog()) + " --keyframe 0 --ground-labels " + quoted(labels) +
                                           " --out " + quoted(other)),
                                "option --ground-labels: needs --frame"));
}

// The landscape view of a keyframe: the pipeline runs inside the command (the matcher untimed by
// the config file, as in the golden test).
TEST(SnapshotCommand, DrawsTheLandscapeViewOfAKeyframe) {
  const fs::path dir = freshOutputDir("snapshot_command_landscape");
  const fs::path config = dir / "config.json", out = dir / "landscape.png";
  std::ofstream(config) << R"({"match": {"time_budget_ms": 1000000}})";
  const CommandResult r = runHdprior("snapshot " + quoted(sharedLog()) + " --keyframe 0 --view landscape --size 640x360 --config " +
                                     quoted(config) + " --out " + quoted(out));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("frame 0"), std::string::npos) << r.out;
  EXPECT_EQ(checkGolden(readPng(out), "real_landscape_view"), "");
}

// A trajectory file as the odometry (`run --odometry`'s options): the run inside the command goes over
// it, and the file_trajectory layer draws it in its magenta.
TEST(SnapshotCommand, DrawsAnOdometryFileAsItsLayer) {
  const SimulatedDrive drive = simulatedTownDrive("snapshot_command_odometry_file", 1, 1, 2.0);  // 20 sweeps, about 16 m
  const fs::path file = writeMovedTruth(drive.log, drive.folder / "given.tum", 0.0, 2.0, 0.0), out = drive.folder / "file.png";
  const CommandResult r = runHdprior("snapshot " + quoted(drive.log) + " --frame 0 --size 640x360 --layers drivable,file_trajectory "
                                     "--odometry " + quoted(file) + " --odometry-frame city --out " + quoted(out));
  ASSERT_EQ(r.status, 0) << r.err;
  const render::Image image = readPng(out);
  size_t magenta = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.pixel(x, y);
      if (p[0] > 180 && p[2] > 180 && p[1] < 140) ++magenta;
    }
  EXPECT_GT(magenta, 40u);  // a 16 m line at 4.75 px/m
}

// BadInput::args: after LOG; --out is added.
class SnapshotCommandBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(SnapshotCommandBadInput, FailsWithOneLineAndNoFile) {
  const fs::path dir = freshOutputDir(std::string("snapshot_bad_") + GetParam().name);
  const fs::path out = dir / "out.png";
  const CommandResult r = runHdprior("snapshot " + quoted(sharedLog()) + " " + GetParam().args + " --out " + quoted(out));
  EXPECT_TRUE(failedWithOneLine(r, GetParam().message));
  EXPECT_TRUE(fs::is_empty(dir)) << "files left behind in " << dir;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SnapshotCommandBadInput,
    ::testing::Values(BadInput{"frame_out_of_range", "--frame 100000", "out of range"},
                      BadInput{"negative_frame", "--frame -1", "negative"},
                      BadInput{"missing_frame", "", "--frame"},
                      BadInput{"bad_size", "--frame 0 --size 12xfoo", "--size"},
                      BadInput{"zero_size", "--frame 0 --size 0x100", "--size"},
                      BadInput{"unknown_layer", "--frame 0 --layers sweep,clouds", "unknown layer"},
                      BadInput{"unknown_view", "--frame 0 --view side", "--view"},
                      BadInput{"keyframe_out_of_range", "--keyframe 5", "out of range"},
                      BadInput{"negative_keyframe", "--keyframe -2", "negative"},
                      BadInput{"landscape_without_keyframe", "--frame 0 --view landscape", "--keyframe"},
                      BadInput{"missing_odometry_file", "--frame 0 --odometry /nonexistent/given.tum", "given.tum"},
                      BadInput{"odometry_frame_alone", "--frame 0 --odometry-frame city", "needs --odometry"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(SnapshotCommand, UnwritableOutputFails) {
  const CommandResult r = runHdprior("snapshot " + quoted(sharedLog()) + " --frame 0 --out /nonexistent/dir/x.png");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/nonexistent/dir/x.png"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists("/nonexistent/dir/x.png"));
}

TEST(SnapshotCommand, OutputThatIsADirectoryFails) {
  const fs::path dir = freshOutputDir("snapshot_out_is_dir");
  const CommandResult r = runHdprior("snapshot " + quoted(sharedLog()) + " --frame 0 --out " + quoted(dir));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(SnapshotCommand, MissingLogFails) {
  const fs::path dir = freshOutputDir("snapshot_missing_log");
  const CommandResult r = runHdprior("snapshot " + quoted(dir / "no_such_log") + " --frame 0 --out " +
                                     quoted(dir / "out.png"));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

}  // namespace
}  // namespace hdprior::test
