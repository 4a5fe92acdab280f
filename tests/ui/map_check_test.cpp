// The bench's map check under Xvfb: after a run, `check-map` draws the changes layer (the street
// drawn too narrow in red, its label in cyan), lists a map-change event at the frame that saw it,
// and `report` counts and scores it (a labelled change it cannot see is a missed-change event);
// the same for a crossing drawn where none is painted and a painted one the map lacks, with the
// painted cells the check read.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "display_run.h"
#include "map_change_labels_file.h"
#include "moved_crossing.h"
#include "narrowed_street.h"
#include "render/image_compare.h"
#include "test_data.h"

namespace hdprior::test {
namespace {
namespace fs = std::filesystem;

// The 3-D view between the panels (layers left, bench right), above the plots.
constexpr int kLeft = 320, kRight = 1280 - 370, kBottom = 800 - 62 - 26 - 170 - 8;

template <class Colour>
size_t pixelsOf(const render::Image& image, Colour colour) {
  size_t n = 0;
  for (int y = 0; y < kBottom; ++y)
    for (int x = kLeft; x < kRight; ++x) n += colour(image.pixel(x, y));
  return n;
}

size_t contradictedPixels(const render::Image& image) {
  return pixelsOf(image, [](const uint8_t* p) { return p[0] > 220 && p[1] < 80 && p[2] < 80; });  // (255, 38, 38)
}

size_t labelledPixels(const render::Image& image) {
  return pixelsOf(image, [](const uint8_t* p) { return p[0] < 70 && p[1] > 200 && p[2] > 200; });  // cyan (26, 242, 242)
}

size_t paintElsewherePixels(const render::Image& image) {
  return pixelsOf(image, [](const uint8_t* p) { return p[0] > 220 && p[1] > 120 && p[1] < 180 && p[2] < 90; });  // orange (255, 153, 26)
}

TEST(MapCheck, CheckMapDrawsTheContradictedStreetAndListsItsEvent) {
  const SimulatedDrive drive = simulatedTownDrive("map_check", 1, 7, 8.0);
  const int64_t narrowed = narrowStreetAtStart(drive.log, 2.5);
  // And a change the check cannot see (labelled near the drive, drawn far from it): a missed-change event.
  const Eigen::Vector2d end = ArgoverseLog(drive.log).cityTEgoAtSweeps().poses().back().translation().head<2>();
  const nlohmann::json unseen = {{"element", "drivable_area"}, {"id", 99}, {"change", "kerb_moved"}, {"route_distance_m", 3.0},
                                 {"changed_stretch", pointsJson({end + Eigen::Vector2d(200, 200), end + Eigen::Vector2d(210, 200)})}};
  writeMapChangeLabels(drive.log, {changedAreaLabel(drive.log, narrowed), unseen});
  const fs::path dir = drive.folder;
  const fs::path before = dir / "before.png", after = dir / "after.png";
  writeText(dir / "script.txt", "run\nview top\nlayer sweep off\nlayer changes on\nwait 2\nscreenshot " + before.string() +
                                    "\ncheck-map\nwait 2\nscreenshot " + after.string() + "\nreport\nevents\n");
  const CommandResult r = runWithDisplay("view " + quoted(drive.log) + " --script " + quoted(dir / "script.txt"), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("map check: 1 drivable areas contradicted"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("map-change drivable area " + std::to_string(narrowed) + ": kerb"), std::string::npos) << r.out;
  EXPECT_GT(contradictedPixels(readPng(after)), contradictedPixels(readPng(before)) + 200) << after;
  // The log's labelled change is drawn with the check and scored in the report.
  EXPECT_GT(labelledPixels(readPng(after)), labelledPixels(readPng(before)) + 200) << after;
  EXPECT_NE(r.out.find("against map_change.json: drivable areas 1 of 1 reports near a change, 1 of 2 changes found"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("missed-change kerb_moved drivable_area 99, 3.0 m from the drive, not reported"), std::string::npos) << r.out;
}

TEST(MapCheck, CrossingsTheLidarContradictsAreCountedAndListedAsEvents) {
  const SimulatedDrive drive = simulatedTownDrive("map_check_crossings", 1, 0, 6.0);
  const int64_t drawn = moveACrossing(drive.log).second;
  const fs::path before = drive.folder / "before.png", after = drive.folder / "after.png";
  writeText(drive.folder / "script.txt", "run\nview top\nlayer sweep off\nlayer changes on\nwait 2\nscreenshot " + before.string() +
                                             "\ncheck-map\nwait 1\nscreenshot " + after.string() + "\nreport\nevents\n");
  const CommandResult r = runWithDisplay("view " + quoted(drive.log) + " --script " + quoted(drive.folder / "script.txt"), drive.folder);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("crossings: 1 contradicted"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(", 1 missing\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("map-change crossing " + std::to_string(drawn) + ": no brighter than the road around it"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("map-change unmapped crossing"), std::string::npos) << r.out;
  // The painted cells the checks read, off the map's paint in orange (the unmapped crossing's, the asphalt's marks).
  EXPECT_GT(paintElsewherePixels(readPng(after)), paintElsewherePixels(readPng(before)) + 100) << after;
}

TEST(MapCheck, CheckMapBeforeARunStopsTheScriptAtItsLine) {
  const SimulatedDrive drive = simulatedTownDrive("map_check_early", 1, 7, 8.0);
  writeText(drive.folder / "script.txt", "check-map\n");
  const CommandResult r = runWithDisplay("view " + quoted(drive.log) + " --script " + quoted(drive.folder / "script.txt"), drive.folder);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("script line 1"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("needs a finished run"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hdprior::test
