// `hdprior changes` on a simulated drive: over its own map nothing is contradicted; over a copy
// of the map with the street the drive starts on narrowed, that street is; bad input is one line
// and exit status 2 with nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/io/argoverse_log.h"
#include "engine/io/file_bytes.h"
#include "engine/io/vector_map.h"
#include "test_data.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

nlohmann::json summaryOf(const fs::path& dir) { return nlohmann::json::parse(test::readFileText(dir / "summary.json")); }

bool inside(const Polyline3& polygon, const Eigen::Vector2d& p) {
  bool in = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector3d &a = polygon[i], &b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) in = !in;
  }
  return in;
}

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

// The polygon under the first pose loses 2.5 m on its side to the left of the vehicle: where the
// lidar sees that side's kerb, the road goes on beyond the map's boundary.
TEST_F(ChangesCommand, AStreetTheMapDrawsNarrowerIsContradicted) {
  const fs::path log = test::copySharedTownDrive(1, 7, 8.0, drive_->folder / "narrowed");
  const ArgoverseLog opened(log);
  const fs::path mapFile = opened.mapFiles().vectorMap;
  VectorMap map = readVectorMap(mapFile);
  const SE3 first = opened.cityTEgoAtSweeps().poses().front();
  const Eigen::Vector2d ego = first.translation().head<2>(), left = first.linear().col(1).head<2>().normalized();
  auto area = std::find_if(map.drivableAreas.begin(), map.drivableAreas.end(),
                           [&](const DrivableArea& a) { return inside(a.areaBoundary, ego); });
  ASSERT_NE(area, map.drivableAreas.end());
  // Vertices on the left of the vehicle (more than 1 m) move 2.5 m towards its line.
  for (Eigen::Vector3d& v : area->areaBoundary)
    if ((v.head<2>() - ego).dot(left) > 1.0) v.head<2>() -= 2.5 * left;
  writeFileAtomically(mapFile, vectorMapToJson(map));
  const fs::path out = drive_->folder / "narrowed_out";
  const test::CommandResult r = test::runHdprior("changes " + test::quoted(log) + " --run " +
                                                 test::quoted(drive_->folder / "run") + " --out " + test::quoted(out));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json s = summaryOf(out);
  const auto& ids = s["contradicted_drivable_areas"];
  EXPECT_NE(std::find(ids.begin(), ids.end(), area->id), ids.end()) << s.dump();
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

}  // namespace
}  // namespace hdprior
