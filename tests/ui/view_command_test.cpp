#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bad_input.h"
#include "engine/sim/demo_log.h"
#include "render/image_compare.h"
#include "display_run.h"
#include "test_data.h"

namespace hdprior::test {
namespace {
namespace fs = std::filesystem;

struct Content {
  size_t distinctColors = 0;
  double drivableGrey = 0;   // the drivable raster over the ground: light blue-grey
  double lidarColors = 0;    // saturated Turbo colours of the sweep points
  size_t checkMarks = 0;     // ImGui's checkbox ticks (layer list) in the left panel
  size_t statusText = 0;     // white text pixels in the status bar (bottom 26 rows)
};

Content measure(const render::Image& image) {
  Content c;
  std::set<uint32_t> colors;
  size_t grey = 0, lidar = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.pixel(x, y);
      const int r = p[0], g = p[1], b = p[2];
      colors.insert(uint32_t(r) << 16 | uint32_t(g) << 8 | uint32_t(b));
      const int hi = std::max({r, g, b}), lo = std::min({r, g, b});
      if (lo >= 110 && hi <= 215 && hi - lo <= 30 && b >= r) ++grey;
      if (hi - lo >= 140) ++lidar;
      if (x < 300 && std::abs(r - 66) <= 6 && std::abs(g - 150) <= 6 && std::abs(b - 250) <= 6) ++c.checkMarks;
      if (y >= image.height - 26 && lo >= 230) ++c.statusText;
    }
  }
  const double n = double(image.width) * image.height;
  c.distinctColors = colors.size();
  c.drivableGrey = grey / n;
  c.lidarColors = lidar / n;
  return c;
}

// The scripted session of the issue: load the real log, step 5 frames, toggle layers, take
// window screenshots, exit 0. The screenshots must show the map, the points and the panels,
// and switching the point layers off must remove the points.
TEST(ViewCommand, ScriptedSessionUnderXvfbShowsMapPointsAndPanels) {
  const fs::path dir = freshOutputDir("view_scripted");
  const fs::path all = dir / "all.png", noPoints = dir / "no_points.png", final = dir / "final.png";
  writeText(dir / "script.txt", "wait 3\nstep 1\nstep 1\nstep 1\nstep 1\nstep 1\n"
                                "layer boundary toggle\nlayer boundary toggle\nwait 2\nscreenshot " + all.string() +
                                    "\nlayer sweep off\nlayer accumulated off\nwait 1\nscreenshot " + noPoints.string() +
                                    "\nlayer sweep on\nview top\nwait 2\n");
  const CommandResult r = runWithDisplay(
      "view " + quoted(sharedLog()) + " --script " + quoted(dir / "script.txt") + " --screenshot " + quoted(final), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  for (const fs::path& p : {all, noPoints, final}) ASSERT_TRUE(fs::exists(p)) << p;

  const render::Image image = readPng(all);
  EXPECT_EQ(image.width, 1280);
  EXPECT_EQ(image.height, 800);
  const Content c = measure(image);
  EXPECT_GT(c.distinctColors, 3000u);
  EXPECT_GT(c.drivableGrey, 0.05);
  EXPECT_GT(c.lidarColors, 0.02);
  EXPECT_GT(c.checkMarks, 50u) << "no layer checkboxes: the ImGui layers panel is missing";
  EXPECT_GT(c.statusText, 200u) << "no status bar text";

  const Content without = measure(readPng(noPoints));
  EXPECT_LT(without.lidarColors, c.lidarColors / 4) << "switching the point layers off did not remove the points";
  EXPECT_GT(without.drivableGrey, 0.05);

  const Content top = measure(readPng(final));
  EXPECT_GT(top.lidarColors, 0.005);
  EXPECT_GT(top.distinctColors, 3000u);

  // The view's overlay in the part of the window the panels leave free (x 310..920, y 0..542):
  // colour-bar labels at its bottom right in both views, the scale bar at its bottom left only
  // in the top-down one.
  const auto overlayText = [](const render::Image& shot, int x0, int y0, int x1, int y1) {
    size_t n = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const uint8_t* p = shot.pixel(x, y);
        n += p[0] >= 225 && p[0] <= 245 && std::abs(p[0] - p[1]) < 6 && std::abs(p[1] - p[2]) < 6;
      }
    return n;
  };
  const render::Image orbitShot = readPng(all), topShot = readPng(final);
  EXPECT_GT(overlayText(orbitShot, 700, 440, 920, 542), 100u) << "no colour bar labels";
  EXPECT_GT(overlayText(topShot, 700, 440, 920, 542), 100u) << "no colour bar labels";
  EXPECT_GT(overlayText(topShot, 310, 480, 560, 542), 2 * overlayText(orbitShot, 310, 480, 560, 542) + 50)
      << "no scale bar in the top-down view";
}

// The numbers after `key` in text, e.g. "estimate 1 2 3" -> {1, 2, 3}.
std::vector<double> numbersAfter(const std::string& text, const std::string& key, size_t count) {
  std::vector<double> values;
  const size_t at = text.find(key);
  if (at == std::string::npos) return values;
  std::istringstream in(text.substr(at + key.size()));
  double v;
  while (values.size() < count && in >> v) values.push_back(v);
  return values;
}

// The tuning bench from a script, as its buttons do: run the pipeline, select and match a keyframe
// from an offset start in the NDT panel, optimise; the numbers are the engine's (the same estimate
// as `hdprior match` from the same start) and the window shows the bench.
TEST(ViewCommand, BenchRunsTheMatchAndTheOptimisationOfItsPanels) {
  const fs::path dir = freshOutputDir("view_bench");
  const fs::path ndt = dir / "ndt.png", pgo = dir / "pgo.png";
  writeText(dir / "script.txt", "wait 2\nstep-keyframe\nreport\nrun\nkeyframe 0\noffset 1 0.5 2\nreport\noptimize\ntab NDT\nwait 2\nscreenshot " +
                                    ndt.string() + "\ntab PGO\nwait 2\nreport\n");
  const CommandResult r = runWithDisplay(
      "view " + quoted(sharedLog()) + " --script " + quoted(dir / "script.txt") + " --screenshot " + quoted(pgo), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  // Stepping by hand: the first sweep is the first keyframe, inspected at once.
  EXPECT_NE(r.out.find("bench: sweeps 1/2 keyframes 1\npriors: 1 full\nmatch: keyframe 0 frame 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bench: sweeps 2/2 keyframes 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("solve: iterations"), std::string::npos) << r.out;
  // The drift model the solve learnt from the priors, as the PGO tab shows it.
  const std::vector<double> drift = numbersAfter(r.out, "drift model: ", 1);
  ASSERT_EQ(drift.size(), 1u) << r.out;
  EXPECT_GT(drift[0], 0.0);
  const std::vector<double> estimate = numbersAfter(r.out, "estimate ", 3);
  ASSERT_EQ(estimate.size(), 3u) << r.out;

  const CommandResult cli = runHdprior("match " + quoted(sharedLog()) + " --frame 0 --init 1,0.5,2");
  ASSERT_EQ(cli.status, 0) << cli.err;
  const std::string json = cli.out.substr(cli.out.find("\"estimate\""));
  // The bench matches the keyframe's sub-map (the same sweep's points, thinned in another order), so
  // the two agree to the matcher's convergence tolerance (5 mm steps), not to the bit.
  EXPECT_NEAR(std::strtod(json.c_str() + json.find("\"x\":") + 4, nullptr), estimate[0], 0.02) << cli.out;
  EXPECT_NEAR(std::strtod(json.c_str() + json.find("\"y\":") + 4, nullptr), estimate[1], 0.02) << cli.out;
  const std::vector<double> error = numbersAfter(r.out, "lateral ", 1);
  ASSERT_EQ(error.size(), 1u);
  EXPECT_LT(std::abs(error[0]), 0.25);  // the real-data target: back within 0.25 m laterally from 0.5 m off

  for (const fs::path& shot : {ndt, pgo}) {
    const render::Image image = readPng(shot);
    size_t text = 0;  // white text in the bench panel on the right
    for (int y = 40; y < 600; ++y)
      for (int x = image.width - 350; x < image.width - 10; ++x)
        if (image.pixel(x, y)[0] > 200 && image.pixel(x, y)[1] > 200 && image.pixel(x, y)[2] > 200) ++text;
    EXPECT_GT(text, 2000u) << shot << ": the bench panel is missing";
  }
}

// Pixels of the file trajectory's magenta (the layer, and the ATE plot's line) in a region.
size_t magentaPixels(const render::Image& image, int x0, int y0, int x1, int y1) {
  size_t n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const uint8_t* p = image.pixel(x, y);
      if (p[0] > 180 && p[2] > 180 && p[1] < 140) ++n;
    }
  return n;
}

// Top-down with what would cover the file's two poses (at the ego) hidden.
const std::string kOnlyTheFileLayer =
    "view top\nlayer ego off\nlayer sweep off\nlayer keyframes off\nlayer odometry_trajectory off\nlayer optimized_trajectory off\n";

// Issue 17 in the app: open a trajectory file (the log's truth moved 0.3 m, in the city frame), see
// it as its layer and in the ATE plot, run the pipeline over it from the Pipeline tab, and get what
// `hdprior run --odometry` gets; then the same run with the built-in odometry beside the file.
TEST(ViewCommand, RunsThePipelineOverAnOpenedTrajectoryFile) {
  const fs::path dir = freshOutputDir("view_odometry_file");
  const fs::path file = writeMovedTruth(sharedLog(), dir / "given.tum", 0.3, -0.2, 0.0);
  const fs::path opened = dir / "opened.png", ran = dir / "ran.png";
  writeText(dir / "script.txt", "wait 2\nodometry " + file.string() + " tum city\nreport\n" + kOnlyTheFileLayer + "wait 2\nscreenshot " + opened.string() +
                                    "\nrun\nreport\n" + kOnlyTheFileLayer + "wait 2\nscreenshot " + ran.string() + "\nuse-odometry builtin\nrun\nreport\n");
  const CommandResult r = runWithDisplay("view " + quoted(sharedLog()) + " --script " + quoted(dir / "script.txt"), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  // Opened: its layer and its own line in the plot, before any run.
  EXPECT_NE(r.out.find("bench: no session\nodometry file: " + file.string() + " (tum, frame city, 2 poses) used by the next run, "
                       "ate rmse 0.3606\nate plot: [file given.tum]\n"),
            std::string::npos) << r.out;
  // Run over it: the session's odometry is the file, and the plot shows it beside the optimised one.
  EXPECT_NE(r.out.find("odometry: file " + file.string() + " (tum, frame city)\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ate plot: [odometry (file given.tum)] [optimised]\n"), std::string::npos) << r.out;
  // With the checkbox off the run is the built-in odometry's, and the file keeps its own line.
  EXPECT_NE(r.out.find("odometry: built-in lidar odometry\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ate plot: [file given.tum] [odometry (built-in)] [optimised]\n"), std::string::npos) << r.out;

  // The same numbers as the CLI's run over the file.
  const CommandResult cli =
      runHdprior("run " + quoted(sharedLog()) + " --out " + quoted(dir / "cli") + " --odometry " + quoted(file) + " --odometry-frame city");
  ASSERT_EQ(cli.status, 0) << cli.err;
  const std::string metrics = slurp(dir / "cli" / "metrics.json");
  const auto rmseOf = [&](const std::string& section) {
    const size_t at = metrics.find("\"rmse\":", metrics.find("\"ate_translation_m\"", metrics.find("\"" + section + "\": {")));
    return std::strtod(metrics.c_str() + at + 7, nullptr);
  };
  const std::vector<double> ate = numbersAfter(r.out.substr(r.out.find("odometry: file")), "ate rmse: odometry ", 1);
  const std::vector<double> optimized = numbersAfter(r.out.substr(r.out.find("odometry: file")), " optimized ", 1);
  ASSERT_EQ(ate.size(), 1u);
  ASSERT_EQ(optimized.size(), 1u);
  EXPECT_NEAR(ate[0], rmseOf("odometry"), 1e-4) << metrics;
  EXPECT_NEAR(optimized[0], rmseOf("optimized"), 1e-4) << metrics;

  // The window: the file's trajectory in its magenta in the 3-D view and in the plot.
  for (const fs::path& shot : {opened, ran}) {
    const render::Image image = readPng(shot);
    EXPECT_GT(magentaPixels(image, 300, 0, image.width - 360, image.height - 260), 10u) << shot << ": no file trajectory layer";
    EXPECT_GT(magentaPixels(image, 300, image.height - 250, image.width - 360, image.height - 80), 10u) << shot << ": no file line in the plot";
  }
}

// A bad trajectory file opened by a script stops it with the one line naming the file and the line.
TEST(ViewCommand, ScriptStopsAtABadTrajectoryFile) {
  const fs::path dir = freshOutputDir("view_odometry_file_bad");
  writeText(dir / "bad.tum", "# poses\n315966265.2 1 2 3\n");
  writeText(dir / "script.txt", "wait 1\nodometry " + (dir / "bad.tum").string() + "\nrun\n");
  const CommandResult r = runWithDisplay("view " + quoted(sharedLog()) + " --script " + quoted(dir / "script.txt"), dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("bad.tum:2: expected 8 fields"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(ViewCommand, FramesAndExitTakesAScreenshot) {
  const fs::path dir = freshOutputDir("view_frames");
  const fs::path shot = dir / "shot.png";
  const CommandResult r =
      runWithDisplay("view " + quoted(sharedLog()) + " --frames 5 --exit --size 800x600 --screenshot " + quoted(shot), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const render::Image image = readPng(shot);
  EXPECT_EQ(image.width, 800);
  EXPECT_EQ(image.height, 600);
  EXPECT_GT(measure(image).distinctColors, 2000u);
}

// Without a log (and no demo log bundled) the app asks for a directory.
// Without a LOG the app opens the demo town, generated into the cache on first use.
TEST(ViewCommand, WithoutALogOpensTheDemoLog) {
  const fs::path dir = freshOutputDir("view_demo_log");
  const fs::path shot = dir / "shot.png";
  const CommandResult r =
      runWithDisplay("view --frames 3 --exit --screenshot " + quoted(shot), dir, "HDPRIOR_CACHE_DIR=" + quoted(dir / "cache"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("generating the demo log"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_directory(dir / "cache" / ("demo-v" + std::to_string(kDemoLogVersion))));
  const Content c = measure(readPng(shot));
  EXPECT_GT(c.drivableGrey, 0.01);  // the demo's dense points cover most of the road
  EXPECT_GT(c.lidarColors, 0.01);
  EXPECT_GT(c.checkMarks, 50u) << "no layer checkboxes: the demo log did not open";
}

// When the demo log cannot be generated (an unusable cache folder) the app still starts and
// asks for a log directory.
TEST(ViewCommand, WithoutALogOrDemoShowsTheOpenLogPanel) {
  const fs::path dir = freshOutputDir("view_no_log");
  const fs::path shot = dir / "shot.png";
  writeText(dir / "not_a_folder", "x");
  const CommandResult r = runWithDisplay("view --frames 3 --exit --screenshot " + quoted(shot), dir,
                                         "HDPRIOR_CACHE_DIR=" + quoted(dir / "not_a_folder" / "cache"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("no demo log"), std::string::npos) << r.err;
  const render::Image image = readPng(shot);
  // The panel: its title bar, frame and white text in the middle of an otherwise empty window.
  size_t text = 0;
  for (int y = image.height / 2 - 60; y < image.height / 2 + 60; ++y)
    for (int x = image.width / 2 - 300; x < image.width / 2 + 300; ++x)
      if (image.pixel(x, y)[0] > 200 && image.pixel(x, y)[1] > 200 && image.pixel(x, y)[2] > 200) ++text;
  EXPECT_GT(text, 300u);
}

// A corrupt sweep met on the way: the scripted run stops with one line naming the file.
TEST(ViewCommand, ScriptStopsAtACorruptSweep) {
  const fs::path dir = freshOutputDir("view_corrupt_sweep");
  const fs::path log = dir / "log";
  fs::create_directories(log / "sensors" / "lidar");
  for (const char* entry : {"map", "calibration", "city_SE3_egovehicle.feather"})
    fs::create_symlink(fs::absolute(sharedLog() / entry), log / entry);
  std::vector<fs::path> sweeps;
  for (const auto& e : fs::directory_iterator(sharedLog() / "sensors" / "lidar")) sweeps.push_back(e.path());
  std::sort(sweeps.begin(), sweeps.end());
  fs::copy_file(sweeps[0], log / "sensors" / "lidar" / sweeps[0].filename());
  writeText(log / "sensors" / "lidar" / sweeps[1].filename(), "not a feather file");
  writeText(dir / "script.txt", "wait 1\nstep 1\nwait 1\n");
  const fs::path shot = dir / "shot.png";
  const CommandResult r =
      runWithDisplay("view " + quoted(log) + " --script " + quoted(dir / "script.txt") + " --screenshot " + quoted(shot), dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(sweeps[1].filename().string()), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(shot));
}

// The first real sweep's ground segmentation against its real labels, in the app: the agreeing
// ground green (the ground_labels layer, shown at that sweep).
TEST(ViewCommand, ShowsTheGroundSegmentationAgainstRealLabels) {
  const fs::path dir = freshOutputDir("view_ground_labels");
  const fs::path labels = sharedDataDir() / "labels/7fab2350-7eaf-3b7e-a39d-6937a4c1bede/flow_labels.feather";
  const auto greenPixels = [](const render::Image& image) {
    size_t n = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 320; x < 1280 - 370; ++x) n += image.pixel(x, y)[1] > 170 && image.pixel(x, y)[0] < 110 && image.pixel(x, y)[2] < 110;
    return n;
  };
  const fs::path with = dir / "with.png", without = dir / "without.png";
  const CommandResult r = runWithDisplay("view " + quoted(sharedLog()) + " --ground-labels " + quoted(labels) +
                                             " --frames 2 --exit --screenshot " + quoted(with), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(runWithDisplay("view " + quoted(sharedLog()) + " --frames 2 --exit --screenshot " + quoted(without), dir).status, 0);
  EXPECT_GT(greenPixels(readPng(with)), greenPixels(readPng(without)) + 2000);
  // The same labels loaded by a script command, as a user does in a running session.
  const fs::path scripted = dir / "scripted.png";
  writeText(dir / "script.txt", "ground-labels " + labels.string() + " 0\nwait 1\nscreenshot " + scripted.string() + "\nexit\n");
  const CommandResult s = runWithDisplay("view " + quoted(sharedLog()) + " --script " + quoted(dir / "script.txt"), dir);
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_NE(s.out.find("ground labels of frame 0"), std::string::npos) << s.out;
  EXPECT_GT(greenPixels(readPng(scripted)), greenPixels(readPng(without)) + 2000);
}

// A script's labels that are missing or of a sweep the log lacks: one line naming it, exit 2.
TEST(ViewCommand, ScriptedGroundLabelsOfAMissingFileOrFrameFailWithOneLine) {
  const fs::path dir = freshOutputDir("view_ground_labels_bad");
  const fs::path labels = sharedDataDir() / "labels/7fab2350-7eaf-3b7e-a39d-6937a4c1bede/flow_labels.feather";
  for (const auto& [line, message] : {std::pair<std::string, std::string>{"ground-labels " + (dir / "nope.feather").string() + " 0", "nope.feather"},
                                      {"ground-labels " + labels.string() + " 5", "frame 5 is out of range"}}) {
    writeText(dir / "script.txt", line + "\nexit\n");
    const CommandResult r = runWithDisplay("view " + quoted(sharedLog()) + " --script " + quoted(dir / "script.txt"), dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

class ViewCommandBadInput : public ::testing::TestWithParam<BadInput> {};

// Refused before any window opens: one line, exit 2, no display needed.
TEST_P(ViewCommandBadInput, FailsWithOneLine) {
  const fs::path dir = freshOutputDir(std::string("view_bad_") + GetParam().name);
  writeText(dir / "bad_script.txt", "wait 1\nfly away\n");
  writeText(dir / "bad_config.json", "{\"match\": {\"outlier_ratio\": 7}}");
  writeText(dir / "bad.tum", "# poses\n315966265.2 1 2 3\n");
  writeText(dir / "early.tum", "1.0 0 0 0 0 0 0 1\n2.0 1 0 0 0 0 0 1\n");
  std::string args = GetParam().args;
  for (const auto& [key, value] : {std::pair<std::string, std::string>{"LOG", quoted(sharedLog())},
                                   {"DIR", dir.string()},
                                   {"LABELS", quoted(sharedDataDir() / "labels/7fab2350-7eaf-3b7e-a39d-6937a4c1bede/flow_labels.feather")}}) {
    for (size_t at; (at = args.find(key)) != std::string::npos;) args.replace(at, key.size(), value);
  }
  const CommandResult r = runHdprior("view " + args);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(GetParam().message), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ViewCommandBadInput,
    ::testing::Values(BadInput{"missing_log", "/nonexistent/log --frames 1 --exit", "not a log directory"},
                      BadInput{"bad_script", "LOG --script DIR/bad_script.txt", "line 2: unknown command 'fly'"},
                      BadInput{"missing_script", "LOG --script DIR/none.txt", "none.txt"},
                      BadInput{"script_and_frames", "LOG --script DIR/bad_script.txt --frames 2", "--script"},
                      BadInput{"bad_frames", "LOG --frames 0 --exit", "--frames"},
                      BadInput{"screenshot_folder", "LOG --frames 1 --exit --screenshot DIR/no/x.png",
                                   "folder does not exist"},
                      BadInput{"bad_size", "LOG --size 12xfoo", "--size"},
                      BadInput{"missing_config", "LOG --frames 1 --exit --config DIR/none.json", "none.json"},
                      BadInput{"bad_config", "LOG --frames 1 --exit --config DIR/bad_config.json", "outlier_ratio"},
                      BadInput{"bad_odometry", "LOG --frames 1 --exit --odometry DIR/bad.tum", "bad.tum:2: expected 8 fields"},
                      BadInput{"missing_odometry", "LOG --frames 1 --exit --odometry DIR/none.tum", "none.tum"},
                      BadInput{"uncovered_odometry", "LOG --frames 1 --exit --odometry DIR/early.tum", "must cover every sweep"},
                      BadInput{"odometry_frame", "LOG --frames 1 --exit --odometry DIR/early.tum --odometry-frame up",
                                   "first or city"},
                      BadInput{"odometry_format_alone", "LOG --frames 1 --exit --odometry-format tum", "needs --odometry"},
                      BadInput{"labels_of_another_sweep", "LOG --frames 1 --exit --ground-labels LABELS --ground-labels-frame 1",
                               "has 99229 rows, the sweep 99466 points"},
                      BadInput{"labels_frame_range", "LOG --frames 1 --exit --ground-labels LABELS --ground-labels-frame 5",
                               "frame 5 is out of range"},
                      BadInput{"labels_frame_alone", "LOG --frames 1 --exit --ground-labels-frame 1", "needs --ground-labels"},
                      BadInput{"missing_labels", "LOG --frames 1 --exit --ground-labels DIR/none.feather", "none.feather"}),
    [](const auto& info) { return std::string(info.param.name); });

// The events a run has, counted from its keyframes.json alone: rejected and gated keyframes, changes in
// what consecutive used priors fix, and used priors whose error is beyond 3 of their sigmas.
std::map<std::string, size_t> eventsInKeyframesJson(const fs::path& file) {
  std::map<std::string, size_t> counts;
  std::string previous;
  for (const nlohmann::json& k : nlohmann::json::parse(slurp(file))) {
    const nlohmann::json& m = k.at("match");
    const std::string category = m.at("constraint").at("category").get<std::string>();
    if (category == "rejected" || category == "gated") {
      ++counts[category];
      continue;
    }
    if (!previous.empty() && previous != category) ++counts["constraint-change"];
    previous = category;
    if (!k.contains("prior_error")) continue;
    const nlohmann::json& e = k.at("prior_error");
    bool beyond = false;
    for (const char* axis : {"along_m", "lateral_m", "yaw_deg"}) {
      const nlohmann::json& sigma = e.at(std::string("sigma_") + axis);
      beyond |= !sigma.is_null() && std::abs(e.at(axis).get<double>()) > 3.0 * sigma.get<double>();
    }
    if (beyond) ++counts["beyond-3-sigma"];
  }
  return counts;
}

size_t redPixels(const render::Image& image, int x0, int y0, int x1, int y1) {
  size_t n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      if (image.pixel(x, y)[0] > 220 && image.pixel(x, y)[1] < 110 && image.pixel(x, y)[2] < 110) ++n;
  return n;
}

// Pixels within 6 of the events' colour of a constraint change (0.3, 0.65, 1.0).
size_t constraintChangeBluePixels(const render::Image& image, int y0, int y1) {
  size_t n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto p = image.pixel(x, y);
      n += std::abs(int(p[0]) - 77) <= 6 && std::abs(int(p[1]) - 166) <= 6 && std::abs(int(p[2]) - 255) <= 6;
    }
  return n;
}

// The debugging bench: what each prior fixes in the report, Diagnostics plots drawn under the ATE
// plot (the chi2 plot's red gate line), the run's events equal to what `hdprior run` writes in
// keyframes.json (ticks on the timeline), next-event going to the first event's frame, a bookmark.
TEST(ViewCommand, DebuggingBenchPlotsEventsAndBookmarks) {
  const SimulatedDrive drive = simulatedTownDrive("view_debugging_bench", 1, 7, 12.0);
  const fs::path dir = freshOutputDir("view_debugging_bench");
  const fs::path start = dir / "start.png", before = dir / "before.png", after = dir / "after.png";
  writeText(dir / "script.txt", "wait 2\nscreenshot " + start.string() + "\nrun\nwait 2\nscreenshot " + before.string() +
                                    "\nplot chi2 on\nplot sigma_lateral on\nplot error_lateral on\nplot score on\nplot score off\n"
                                    "plot score on\nevents\nnext-event\nbookmark kerb looks off\nreport\nwait 2\nscreenshot " +
                                    after.string() + "\n");
  const CommandResult r = runWithDisplay("view " + quoted(drive.log) + " --script " + quoted(dir / "script.txt"), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("diagnostic plots: [score] [sigma_lateral] [chi2] [error_lateral]\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("priors: "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("degenerate,"), std::string::npos) << r.out;

  const CommandResult run = runHdprior("run " + quoted(drive.log) + " --out " + quoted(dir / "run"));
  ASSERT_EQ(run.status, 0) << run.err;
  const std::map<std::string, size_t> expected = eventsInKeyframesJson(dir / "run" / "keyframes.json");
  std::map<std::string, size_t> shown;
  std::istringstream lines(r.out);
  std::vector<long long> eventFrames;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("event ", 0) != 0) continue;
    std::istringstream words(line);
    std::string event, index, keyframeWord, keyframe, frameWord, kind;
    long long frame = 0;
    words >> event >> index >> keyframeWord >> keyframe >> frameWord >> frame >> kind;
    EXPECT_EQ(keyframeWord + frameWord, "keyframeframe") << line;
    ++shown[kind];
    eventFrames.push_back(frame);
  }
  EXPECT_EQ(shown, expected) << r.out;
  ASSERT_FALSE(eventFrames.empty()) << r.out;  // at least the change from full priors at the start to lateral + yaw
  EXPECT_NE(r.out.find("frame " + std::to_string(eventFrames.front()) + "\nbookmark 0 frame " +
                       std::to_string(eventFrames.front()) + " kerb looks off\n"),
            std::string::npos)
      << r.out;

  // The plots' band (two rows of 96 px under the 170 px ATE plot, above the timeline) gains the gate's red.
  const render::Image a = readPng(before), b = readPng(after);
  const int x0 = 310, x1 = a.width - 360, y0 = a.height - 88 - 192, y1 = a.height - 88;
  EXPECT_GT(redPixels(b, x0, y0, x1, y1), redPixels(a, x0, y0, x1, y1) + 100) << after;
  // The timeline (the bottom 88 px) gains a tick per event: a constraint change's blue at least.
  EXPECT_GE(constraintChangeBluePixels(a, a.height - 88, a.height), constraintChangeBluePixels(readPng(start), a.height - 88, a.height) + 5)
      << before;
}

// Without an X server the window cannot open: one line naming GLFW, never a crash.
TEST(ViewCommand, WithoutADisplaySaysSo) {
  const CommandResult r = runHdprior("view " + quoted(sharedLog()) + " --frames 1 --exit");
  if (std::getenv("DISPLAY")) GTEST_SKIP() << "a display is available";
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("GLFW"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace hdprior::test
