// `hdprior changes` on a simulated drive: over its own map nothing is contradicted; over a copy
// of the map with the street the drive starts on narrowed, that street is; a painted crossing the
// map lacks is missing and one it draws without paint contradicted; bad input is one line and exit
// status 2 with nothing written. And on the real log over its real map.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/geom/polygon2d.h"
#include "engine/io/file_bytes.h"
#include "moved_crossing.h"
#include "moved_lane_line.h"
#include "narrowed_street.h"
#include "test_data.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

nlohmann::json summaryOf(const fs::path& dir) { return nlohmann::json::parse(test::readFileText(dir / "summary.json")); }

class ChangesCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    drive_ = new test::SimulatedDrive(test::simulatedTownDrive("changes_command", 1, 7, 8.0));
    const test::CommandResult r = test::runHdprior("run " + test::quoted(drive_->log) + " --out " + test::quoted(drive_->folder / "run"));
    ASSERT_EQ(r.status, 0) << r.err;
  }
  static void TearDownTestSuite() { delete drive_; }
  static test::SimulatedDrive* drive_;
};
test::SimulatedDrive* ChangesCommand::drive_ = nullptr;

TEST_F(ChangesCommand, OverItsOwnMapNothingIsContradicted) {
  const fs::path out = drive_->folder / "same";
  const test::CommandResult r = test::runHdprior("changes " + test::quoted(drive_->log) + " --run " +
                                                 test::quoted(drive_->folder / "run") + " --out " + test::quoted(out));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json s = summaryOf(out);
  EXPECT_GT(s["frames"].get<int>(), 10);
  EXPECT_GT(s["driven_km"].get<double>(), 0.03);
  EXPECT_GT(s["observed_boundary_km"].get<double>(), 0.02);
  EXPECT_GE(s["drivable_areas"]["consistent"].get<int>(), 1);
  EXPECT_EQ(s["drivable_areas"]["contradicted"].get<int>(), 0) << s.dump();
  EXPECT_EQ(s["missing_surfaces"].get<int>(), 0) << s.dump();
  const nlohmann::json geo = nlohmann::json::parse(test::readFileText(out / "changes.geojson"));
  EXPECT_EQ(geo["type"], "FeatureCollection");
  EXPECT_FALSE(geo["features"].empty());
}

// The street under the first pose drawn 2.5 m narrower on its left: where the lidar sees that
// side's kerb, the road goes on beyond the map's boundary.
TEST_F(ChangesCommand, AStreetTheMapDrawsNarrowerIsContradicted) {
  const fs::path log = test::copySharedTownDrive(1, 7, 8.0, drive_->folder / "narrowed");
  const int64_t narrowed = test::narrowStreetAtStart(log, 2.5);
  const fs::path out = drive_->folder / "narrowed_out";
  const test::CommandResult r = test::runHdprior("changes " + test::quoted(log) + " --run " +
                                                 test::quoted(drive_->folder / "run") + " --out " + test::quoted(out));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json s = summaryOf(out);
  const auto& ids = s["contradicted_drivable_areas"];
  EXPECT_NE(std::find(ids.begin(), ids.end(), narrowed), ids.end()) << s.dump();
}

TEST_F(ChangesCommand, BadInputIsOneLineAndNothingIsWritten) {
  const fs::path out = drive_->folder / "bad";
  const fs::path empty = drive_->folder / "empty_run";
  fs::create_directories(empty);
  EXPECT_TRUE(test::failedWithOneLine(
      test::runHdprior("changes " + test::quoted(drive_->log) + " --run " + test::quoted(empty) + " --out " + test::quoted(out)),
      "has neither optimized.tum nor odometry.tum"));
  EXPECT_TRUE(test::failedWithOneLine(test::runHdprior("changes " + test::quoted(drive_->log) + " --run " +
                                                       test::quoted(drive_->folder / "nowhere") + " --out " + test::quoted(out)),
                                      "is not a run folder"));
  writeFileAtomically(empty / "optimized.tum", std::string("1 2 3\n"));
  EXPECT_TRUE(test::failedWithOneLine(
      test::runHdprior("changes " + test::quoted(drive_->log) + " --run " + test::quoted(empty) + " --out " + test::quoted(out)),
      "optimized.tum"));
  EXPECT_FALSE(fs::exists(out / "changes.geojson"));
  EXPECT_FALSE(fs::exists(out / "summary.json"));
}

// `hdprior run` of a drive into its folder's run/.
::testing::AssertionResult runDrive(const test::SimulatedDrive& drive) {
  const test::CommandResult r = test::runHdprior("run " + test::quoted(drive.log) + " --out " + test::quoted(drive.folder / "run"));
  if (r.status != 0) return ::testing::AssertionFailure() << r.err;
  return ::testing::AssertionSuccess();
}

// `hdprior changes` of the drive along that run into its folder's `name`/; its summary.json.
nlohmann::json changesOverTheRun(const test::SimulatedDrive& drive, const std::string& name) {
  const test::CommandResult r = test::runHdprior("changes " + test::quoted(drive.log) + " --run " + test::quoted(drive.folder / "run") +
                                                 " --out " + test::quoted(drive.folder / name));
  EXPECT_EQ(r.status, 0) << r.err;
  return summaryOf(drive.folder / name);
}

// Town 1's 6 s drive passes over two painted crossings.
TEST(ChangesCommandCrossings, APaintedCrossingTheMapLacksIsMissingAndADrawnOneWithoutPaintIsContradicted) {
  const test::SimulatedDrive drive = test::simulatedTownDrive("changes_crossings", 1, 0, 6.0);
  ASSERT_TRUE(runDrive(drive));
  const auto changes = [&](const std::string& name) { return changesOverTheRun(drive, name); };
  const nlohmann::json own = changes("own");
  EXPECT_GE(own["pedestrian_crossings"]["consistent"].get<int>(), 2) << own.dump();
  EXPECT_EQ(own["pedestrian_crossings"]["contradicted"].get<int>(), 0) << own.dump();
  EXPECT_EQ(own["missing_crossings"].get<int>(), 0) << own.dump();

  const auto [removed, drawn] = test::moveACrossing(drive.log);
  const nlohmann::json moved = changes("moved");
  EXPECT_EQ(moved["missing_crossings"].get<int>(), 1) << moved.dump();
  EXPECT_EQ(moved["pedestrian_crossings"]["contradicted"].get<int>(), 1) << moved.dump();
  const nlohmann::json geo = nlohmann::json::parse(test::readFileText(drive.folder / "moved" / "changes.geojson"));
  bool foundMissing = false, foundDrawn = false;
  for (const nlohmann::json& f : geo["features"]) {
    const nlohmann::json& p = f["properties"];
    if (p["element"] != "pedestrian_crossing") continue;
    if (p["verdict"] == "contradicted") foundDrawn |= p["id"] == drawn && p["change"] == "insert_crosswalk";
    if (p["verdict"] != "missing") continue;
    Ring2 outline;
    for (const auto& xy : f["geometry"]["coordinates"][0]) outline.emplace_back(xy[0].get<double>(), xy[1].get<double>());
    outline.pop_back();
    foundMissing |= p["change"] == "delete_crosswalk" && polylineDistance(std::vector<Eigen::Vector2d>{removed}, outline, true) < 3.0;
  }
  EXPECT_TRUE(foundMissing) << "no missing crossing near (" << removed.transpose() << ")";
  EXPECT_TRUE(foundDrawn);
}

// The same drive with the lane line nearest to its start drawn 1.2 m to the line's left: where the
// lidar sees that line's paint, the map's line is contradicted, the paint 1.2 m to its right.
TEST(ChangesCommandLaneLines, ALaneLineDrawnBesideItsPaintIsContradicted) {
  const test::SimulatedDrive drive = test::simulatedTownDrive("changes_lane_lines", 1, 0, 6.0);
  ASSERT_TRUE(runDrive(drive));
  const auto changes = [&](const std::string& name) { return changesOverTheRun(drive, name); };
  const nlohmann::json own = changes("own");
  EXPECT_GE(own["lane_line_stretches"]["consistent"].get<int>(), 2) << own.dump();
  EXPECT_EQ(own["lane_line_stretches"]["contradicted"].get<int>(), 0) << own.dump();

  test::moveALaneLine(drive.log, 1.2);
  const nlohmann::json moved = changes("moved");
  EXPECT_GE(moved["lane_line_stretches"]["contradicted"].get<int>(), 1) << moved.dump();
  const nlohmann::json geo = nlohmann::json::parse(test::readFileText(drive.folder / "moved" / "changes.geojson"));
  int contradicted = 0;
  for (const nlohmann::json& f : geo["features"]) {
    const nlohmann::json& p = f["properties"];
    if (p["element"] != "lane_boundary" || p["verdict"] != "contradicted") continue;
    ++contradicted;
    EXPECT_NEAR(std::abs(p["evidence"]["offset_m"].get<double>()), 1.2, 0.3) << p.dump();
    EXPECT_EQ(p["change"], "lane_geometry_change");
  }
  EXPECT_GE(contradicted, 1);
}

// The real log over its own map (one sweep used: the two are 7 cm apart): the kerbs the sweep shows
// agree with the drivable area, nothing is contradicted and no surface is missing.
TEST(ChangesCommandReal, TheRealSweepAgreesWithItsMap) {
  const fs::path dir = test::freshOutputDir("changes_real");
  const test::CommandResult run = test::runHdprior("run " + test::quoted(test::sharedLog()) + " --out " + test::quoted(dir / "run"));
  ASSERT_EQ(run.status, 0) << run.err;
  const test::CommandResult r = test::runHdprior("changes " + test::quoted(test::sharedLog()) + " --run " + test::quoted(dir / "run") +
                                                 " --out " + test::quoted(dir / "changes"));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json s = summaryOf(dir / "changes");
  EXPECT_GE(s["drivable_areas"]["consistent"].get<int>(), 1) << s.dump();
  EXPECT_GT(s["observed_boundary_km"].get<double>(), 0.02) << s.dump();
  EXPECT_EQ(s["drivable_areas"]["contradicted"].get<int>(), 0) << s.dump();
  EXPECT_EQ(s["missing_surfaces"].get<int>(), 0) << s.dump();
  // The one sweep shows the painted edges of the crossing 8-12 m ahead: more of its cells hold paint
  // than of the asphalt's, too few to call it painted (the road's own marks are as bright), and
  // nothing contradicts a crossing.
  EXPECT_EQ(s["pedestrian_crossings"]["contradicted"].get<int>(), 0) << s.dump();
  EXPECT_EQ(s["missing_crossings"].get<int>(), 0) << s.dump();
  const nlohmann::json geo = nlohmann::json::parse(test::readFileText(dir / "changes" / "changes.geojson"));
  bool ahead = false;
  for (const nlohmann::json& f : geo["features"]) {
    const nlohmann::json& p = f["properties"];
    if (p["element"] != "pedestrian_crossing" || p["id"] != 2356430) continue;
    const nlohmann::json& e = p["evidence"];
    ahead = e["road_cells"].get<int>() >= 50 &&
            e["paint_cells"].get<double>() > 1.2 * e["asphalt_paint_share"].get<double>() * e["road_cells"].get<double>();
  }
  EXPECT_TRUE(ahead) << "crossing 2356430: no more paint than the asphalt's";
  // The lane lines within 8 m: the sweep's few rings there cross them in a handful of road cells
  // (2-5 per quarter metre beside a line), too few for a verdict either way.
  int laneCells = 0;
  for (const nlohmann::json& f : geo["features"]) {
    const nlohmann::json& p = f["properties"];
    if (p["element"] != "lane_boundary") continue;
    EXPECT_EQ(p["verdict"], "unobserved") << p.dump();
    laneCells += p["evidence"]["road_cells_on_line"].get<int>();
  }
  EXPECT_GE(laneCells, 5);
  EXPECT_EQ(s["lane_line_stretches"]["contradicted"].get<int>(), 0) << s.dump();
}

}  // namespace
}  // namespace hdprior
