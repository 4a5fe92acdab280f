// The bench's map check under Xvfb: after a run, `check-map` draws the changes layer (the street
// drawn too narrow in red), lists a map-change event at the frame that saw it, and `report` counts it;
// the same for a crossing drawn where none is painted and a painted one the map lacks.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "display_run.h"
#include "moved_crossing.h"
#include "narrowed_street.h"
#include "render/image_compare.h"
#include "test_data.h"

namespace hdprior::test {
namespace {
namespace fs = std::filesystem;

// The 3-D view between the panels (layers left, bench right), above the plots.
constexpr int kLeft = 320, kRight = 1280 - 370, kBottom = 800 - 62 - 26 - 170 - 8;

size_t contradictedPixels(const render::Image& image) {
  size_t n = 0;
  for (int y = 0; y < kBottom; ++y)
    for (int x = kLeft; x < kRight; ++x) {
      const uint8_t* p = image.pixel(x, y);
      n += p[0] > 220 && p[1] < 80 && p[2] < 80;  // the layer's contradicted red (255, 38, 38)
    }
  return n;
}

TEST(MapCheck, CheckMapDrawsTheContradictedStreetAndListsItsEvent) {
  const SimulatedDrive drive = simulatedTownDrive("map_check", 1, 7, 8.0);
  const int64_t narrowed = narrowStreetAtStart(drive.log, 2.5);
  const fs::path dir = drive.folder;
  const fs::path before = dir / "before.png", after = dir / "after.png";
  writeText(dir / "script.txt", "run\nview top\nlayer sweep off\nlayer changes on\nwait 2\nscreenshot " + before.string() +
                                    "\ncheck-map\nwait 2\nscreenshot " + after.string() + "\nreport\nevents\n");
  const CommandResult r = runWithDisplay("view " + quoted(drive.log) + " --script " + quoted(dir / "script.txt"), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("map check: 1 drivable areas contradicted"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("map-change drivable area " + std::to_string(narrowed) + ": kerb"), std::string::npos) << r.out;
  EXPECT_GT(contradictedPixels(readPng(after)), contradictedPixels(readPng(before)) + 200) << after;
}

TEST(MapCheck, CrossingsTheLidarContradictsAreCountedAndListedAsEvents) {
  const SimulatedDrive drive = simulatedTownDrive("map_check_crossings", 1, 0, 6.0);
  const int64_t drawn = moveACrossing(drive.log).second;
  writeText(drive.folder / "script.txt", "run\ncheck-map\nwait 1\nreport\nevents\n");
  const CommandResult r = runWithDisplay("view " + quoted(drive.log) + " --script " + quoted(drive.folder / "script.txt"), drive.folder);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("crossings: 1 contradicted"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(", 1 missing\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("map-change crossing " + std::to_string(drawn) + ": no paint"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("map-change unmapped crossing"), std::string::npos) << r.out;
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
