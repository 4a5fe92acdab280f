// The debugging bench under Xvfb: run B beside run A (compare), measure, pick, and sessions saved,
// restored and drawn headless.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "display_run.h"
#include "engine/geom/se2.h"
#include "engine/io/argoverse_log.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/point_labels.h"
#include "render/image_compare.h"
#include "test_data.h"
#include "ui/view_session.h"

namespace hdprior::test {
namespace {
namespace fs = std::filesystem;

// The words after `key` in `text` (its first occurrence) that are numbers, as many as asked for.
std::vector<double> numericWordsAfter(const std::string& text, const std::string& key, size_t count) {
  std::vector<double> out;
  const size_t at = text.find(key);
  if (at == std::string::npos) return out;
  std::istringstream in(text.substr(at + key.size()));
  std::string word;
  while (out.size() < count && in >> word) {
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (end != word.c_str() && *end == '\0') out.push_back(v);
  }
  return out;
}

// Pixels near a colour in a region of a screenshot.
size_t pixelsNear(const render::Image& image, int x0, int y0, int x1, int y1, int r, int g, int b, int tolerance) {
  size_t n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const uint8_t* p = image.pixel(x, y);
      n += std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance && std::abs(p[2] - b) <= tolerance;
    }
  return n;
}

double optimizedRmse(const fs::path& runDir) {
  const nlohmann::json m = nlohmann::json::parse(slurp(runDir / "metrics.json"));
  return m.at("optimized").at("ate_translation_m").at("rmse").get<double>();
}

// The 3-D view between the panels (layers left, bench right), above the plots.
constexpr int kViewLeft = 320, kViewRight = 1280 - 370, kViewBottom = 800 - 62 - 26 - 170 - 8;

// No wall-clock budget for a match: under the test machine's load a match may take longer than the
// default 100 ms, and the app and `hdprior run` must reject the same matches.
const char* kNoBudget = R"({"match": {"time_budget_ms": 100000}})";
const char* kOtherB = R"({"match": {"time_budget_ms": 100000, "outlier_ratio": 0.3, "min_inlier_ratio": 0.6}})";

// Run B from a config file: `report` gives both ATE RMSEs as `hdprior run` writes them (1e-4), the
// view draws B's trajectory (mint) where it drew none, and `measure match` measures the match from
// its estimate to the truth (the report's match error, reversed).
TEST(DebuggingBench, CompareRunsBAsRunDoesAndDrawsIt) {
  const SimulatedDrive drive = simulatedTownDrive("bench_compare", 1, 7, 8.0);
  const fs::path dir = freshOutputDir("bench_compare");
  const fs::path before = dir / "before.png", after = dir / "after.png";
  writeText(dir / "a.json", kNoBudget);
  writeText(dir / "b.json", kOtherB);
  writeText(dir / "script.txt", "run\nwait 2\nscreenshot " + before.string() + "\ncompare " + (dir / "b.json").string() +
                                    "\nplot score on\nwait 3\nscreenshot " + after.string() +
                                    "\nkeyframe 2\nreport\nmeasure match\noffset 0.5 0 0\nreport\ntab Compare\nwait 2\n");
  const CommandResult r = runWithDisplay("view " + quoted(drive.log) + " --config " + quoted(dir / "a.json") + " --script " +
                                             quoted(dir / "script.txt") + " --screenshot " + quoted(dir / "compare_tab.png"),
                                         dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<double> ab = numericWordsAfter(r.out, "compare: A ate_rmse", 2);
  ASSERT_EQ(ab.size(), 2u) << r.out;

  for (const auto& [config, out] : {std::pair{"a.json", "runA"}, std::pair{"b.json", "runB"}}) {
    const CommandResult run = runHdprior("run " + quoted(drive.log) + " --config " + quoted(dir / config) + " --out " + quoted(dir / out));
    ASSERT_EQ(run.status, 0) << run.err;
  }
  EXPECT_NEAR(ab[0], optimizedRmse(dir / "runA"), 1e-4) << r.out;
  EXPECT_NEAR(ab[1], optimizedRmse(dir / "runB"), 1e-4) << r.out;
  EXPECT_NE(ab[0], ab[1]) << "B's configuration should change the run";

  // B's trajectory in its mint (77, 255, 191) over the view; none before B ran.
  const render::Image a = readPng(before), b = readPng(after);
  const size_t yellowBefore = pixelsNear(a, kViewLeft, 0, kViewRight, kViewBottom, 77, 255, 191, 30);
  const size_t yellowAfter = pixelsNear(b, kViewLeft, 0, kViewRight, kViewBottom, 77, 255, 191, 30);
  EXPECT_GT(yellowAfter, yellowBefore + 100) << after;
  // And in the plots under the view (ATE and score), B's lines in the same mint.
  EXPECT_GT(pixelsNear(b, 310, kViewBottom, 1280 - 360, 800 - 88, 77, 255, 191, 30),
            pixelsNear(a, 310, kViewBottom, 1280 - 360, 800 - 88, 77, 255, 191, 30) + 100)
      << after;

  const std::vector<double> error = numericWordsAfter(r.out, "match error: along", 2);
  const std::vector<double> measured = numericWordsAfter(r.out, "measure: distance", 3);
  ASSERT_EQ(error.size(), 2u) << r.out;
  ASSERT_EQ(measured.size(), 3u) << r.out;
  EXPECT_NEAR(measured[1], -error[0], 1e-3) << r.out;  // along: from the estimate to the truth
  EXPECT_NEAR(measured[2], -error[1], 1e-3) << r.out;
  EXPECT_NEAR(measured[0], std::hypot(error[0], error[1]), 1e-3) << r.out;
  // The NDT tab's history: the keyframe's match, then the re-match from the offset, with what changed.
  EXPECT_NE(r.out.find("history: 1 rows, last: first match => "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("history: 2 rows, last: start offset (0.00, 0.00, 0.0 deg) -> (0.50, 0.00, 0.0 deg) => "), std::string::npos)
      << r.out;
}

// A constructed pair on the real log's frame 0: 3 m along the ego heading and 2 m to its right,
// measured to 1 cm and drawn; a pick at a sweep point names that point, its label as the road
// points label it, and the drivable area under it.
TEST(DebuggingBench, MeasureAndPickOnTheRealLog) {
  const ArgoverseLog log(sharedLog());
  const SE3 pose = log.cityTEgoAtSweeps().poses().front();
  const Eigen::Vector3d planar = planarPose(pose);
  const Eigen::Vector3d from = offsetPose(planar, {4.0, 1.0, 0.0}), to = offsetPose(from, {3.0, -2.0, 0.0});

  const std::shared_ptr<const LidarSweep> sweep = log.sweep(0);
  const std::vector<SubmapLabel> labels = sweepPointLabels(*sweep, pose, defaultConfig().roadPoints);
  size_t road = labels.size();  // the first road point 6-10 m away
  for (size_t i = 0; i < labels.size() && road == labels.size(); ++i) {
    const LidarPoint& p = sweep->points[i];
    if (labels[i] == SubmapLabel::Road && std::hypot(p.x, p.y) > 6 && std::hypot(p.x, p.y) < 10) road = i;
  }
  ASSERT_LT(road, labels.size());
  const LidarPoint& p = sweep->points[road];
  const Eigen::Vector3d city = pose * Eigen::Vector3d(p.x, p.y, p.z);

  const fs::path dir = freshOutputDir("bench_measure_pick");
  const fs::path before = dir / "before.png", after = dir / "after.png";
  char script[512];
  std::snprintf(script, sizeof script, "view top\nwait 2\nscreenshot %s\nmeasure %.6f %.6f %.6f %.6f\npick %.6f %.6f\nwait 2\n",
                before.c_str(), from.x(), from.y(), to.x(), to.y(), city.x(), city.y());
  writeText(dir / "script.txt", script);
  const CommandResult r =
      runWithDisplay("view " + quoted(sharedLog()) + " --script " + quoted(dir / "script.txt") + " --screenshot " + quoted(after), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<double> m = numericWordsAfter(r.out, "measure: distance", 3);
  ASSERT_EQ(m.size(), 3u) << r.out;
  EXPECT_NEAR(m[0], std::sqrt(13.0), 0.01);
  EXPECT_NEAR(m[1], 3.0, 0.01);
  EXPECT_NEAR(m[2], -2.0, 0.01);
  const std::string expected = "pick: road point " + std::to_string(road) + " (0.00 m away) range ";
  EXPECT_NE(r.out.find(expected), std::string::npos) << r.out;
  char detail[96];
  std::snprintf(detail, sizeof detail, "intensity %d laser %d", int(p.intensity), int(p.laserNumber));
  EXPECT_NE(r.out.find(detail), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("; drivable area "), std::string::npos) << r.out;  // a road point 6-10 m ahead lies on the road

  // The measure line's yellow (255, 255, 51) appears in the view.
  const size_t lineBefore = pixelsNear(readPng(before), kViewLeft, 0, kViewRight, kViewBottom, 255, 255, 51, 40);
  const size_t lineAfter = pixelsNear(readPng(after), kViewLeft, 0, kViewRight, kViewBottom, 255, 255, 51, 40);
  EXPECT_GT(lineAfter, lineBefore + 30) << after;
}

// Saved with runs A and B, a keyframe, plots, layers, a bookmark and a tab, a session opened again
// with `view --session` gives the same window (the status bar's FPS aside), and `snapshot --session`
// draws it headless.
TEST(DebuggingBench, ASavedSessionRestoresTheSameView) {
  const SimulatedDrive drive = simulatedTownDrive("bench_session", 1, 7, 8.0);
  const fs::path dir = freshOutputDir("bench_session");
  const fs::path saved = dir / "saved.png", restored = dir / "restored.png", session = dir / "session.json";
  writeText(dir / "a.json", kNoBudget);
  writeText(dir / "b.json", kOtherB);
  writeText(dir / "save.txt", "run\ncompare " + (dir / "b.json").string() +
                                  "\nkeyframe 3\nplot chi2 on\nplot sigma_lateral on\nlayer lanes off\nbookmark look here\ntab Events\n"
                                  "wait 3\nsave-session " + session.string() + "\nscreenshot " + saved.string() + "\n");
  const CommandResult first = runWithDisplay(
      "view " + quoted(drive.log) + " --config " + quoted(dir / "a.json") + " --script " + quoted(dir / "save.txt"), dir);
  ASSERT_EQ(first.status, 0) << first.err;
  const ui::ViewSession s = ui::readViewSession(session);
  EXPECT_TRUE(s.ran);
  ASSERT_TRUE(s.comparison.has_value());
  EXPECT_EQ(s.comparison->name, "b.json");
  EXPECT_EQ(s.keyframe, std::optional<size_t>(3));
  EXPECT_EQ(s.plots, (std::vector<std::string>{"sigma_lateral", "chi2"}));
  ASSERT_EQ(s.bookmarks.size(), 1u);
  EXPECT_EQ(s.bookmarks[0].note, "look here");
  EXPECT_EQ(s.tab, "Events");

  writeText(dir / "restore.txt", "wait 3\nscreenshot " + restored.string() + "\n");
  const CommandResult second = runWithDisplay("view --session " + quoted(session) + " --script " + quoted(dir / "restore.txt"), dir);
  ASSERT_EQ(second.status, 0) << second.err;
  render::Image a = readPng(saved), b = readPng(restored);
  ASSERT_EQ(a.width, b.width);
  // The status bar (FPS) is live; everything above it must match.
  a.height = b.height = a.height - 26;
  a.rgba.resize(size_t(a.width) * a.height * 4);
  b.rgba.resize(size_t(b.width) * b.height * 4);
  const ImageDifference d = compareImages(b, a, 8);
  EXPECT_LT(d.differingFraction, 0.002) << d.differingPixels << " pixels differ: " << saved << " vs " << restored;

  const CommandResult snap = runHdprior("snapshot --session " + quoted(session) + " --out " + quoted(dir / "snapshot.png"));
  ASSERT_EQ(snap.status, 0) << snap.err;
  const render::Image headless = readPng(dir / "snapshot.png");
  EXPECT_GT(pixelsNear(headless, 0, 0, headless.width, headless.height, 77, 255, 191, 30), 100u) << "no B trajectory";
}

// A session of the real log without runs, written here, drawn headless: the golden image.
TEST(DebuggingBench, SnapshotOfASessionMatchesItsGolden) {
  const ArgoverseLog log(sharedLog());
  ui::ViewSession s;
  s.log = sharedLog();
  s.frame = 1;
  s.camera.target = log.cityTEgoAtSweeps().poses()[1].translation();
  s.camera.followEgo = false;
  s.camera.yaw = 0.7;
  s.camera.pitch = 0.9;
  s.camera.distance = 45.0;
  s.layers = {{"ground", true, 1.0f}, {"drivable", true, 0.6f}, {"boundary", true, 1.0f}, {"sweep", true, 1.0f}, {"lanes", false, 1.0f}};
  s.config = formatConfig(defaultConfig());
  const fs::path dir = freshOutputDir("bench_session_golden");
  ui::writeViewSession(dir / "session.json", s);
  const CommandResult r = runHdprior("snapshot --session " + quoted(dir / "session.json") + " --out " + quoted(dir / "s.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(checkGolden(readPng(dir / "s.png"), "session_orbit"), "");

  const CommandResult both = runHdprior("snapshot " + quoted(sharedLog()) + " --session " + quoted(dir / "session.json") +
                                        " --frame 0 --out " + quoted(dir / "t.png"));
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("option --session: cannot be combined with --frame"), std::string::npos) << both.err;
  writeText(dir / "bad.json", "{\"hdprior_view_session\": 1, \"log\": 3}");
  const CommandResult bad = runHdprior("snapshot --session " + quoted(dir / "bad.json") + " --out " + quoted(dir / "u.png"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("bad.json"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "u.png"));
}

}  // namespace
}  // namespace hdprior::test
