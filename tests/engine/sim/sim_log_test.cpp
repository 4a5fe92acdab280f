// Simulated logs read back through the normal loader: ground truth labels, poses and map
// agree; output is deterministic; bad options fail cleanly with nothing left behind.
#include "engine/sim/log_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/io/argoverse_log.h"
#include "engine/io/feather.h"
#include "engine/io/file_bytes.h"
#include "engine/io/vector_map.h"
#include "engine/map/drivable_raster.h"
#include "engine/map/ground_height.h"
#include "engine/sim/scene.h"
#include "test_data.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

std::vector<uint8_t> readLabels(const fs::path& log, int64_t ts) {
  const arrow::Table t = arrow::readFeather(log / "sensors" / "lidar_labels" / (std::to_string(ts) + ".feather"));
  const auto v = t.column("label", arrow::Type::UInt8, "labels").as<uint8_t>();
  return {v.begin(), v.end()};
}

// For the first `n` sweeps: road-labelled points placed with the ground-truth pose lie on
// the ground-height surface and inside the drivable area.
void checkRoadPoints(const fs::path& dir, size_t n) {
  const ArgoverseLog log(dir);
  ASSERT_GE(log.sweepCount(), n);
  const VectorMap map = readVectorMap(log.mapFiles().vectorMap);
  const GroundHeight ground = readGroundHeight(log.mapFiles().groundHeight, log.mapFiles().sim2);
  // Only the drivable areas near the drive (a town is large); 0.1 m like the HD map.
  const Eigen::Vector2d start = log.cityTEgo().poses().front().translation().head<2>();
  VectorMap near;
  for (const DrivableArea& a : map.drivableAreas)
    for (const Eigen::Vector3d& v : a.areaBoundary)
      if ((v.head<2>() - start).norm() < 400.0) {
        near.drivableAreas.push_back(a);
        break;
      }
  const DrivableRaster raster = DrivableRaster::build(near, {}, "test");
  for (size_t i = 0; i < n; ++i) {
    const auto sweep = log.sweep(i);
    const std::vector<uint8_t> labels = readLabels(dir, sweep->timestampNs);
    ASSERT_EQ(labels.size(), sweep->points.size()) << "sweep " << i;
    const SE3 cityTEgo = log.cityTEgo().at(sweep->timestampNs);
    std::vector<double> dz;
    size_t inside = 0, road = 0;
    for (size_t k = 0; k < labels.size(); ++k) {
      if (labels[k] != uint8_t(PointLabel::Road)) continue;
      ++road;
      const LidarPoint& p = sweep->points[k];
      const Eigen::Vector3d c = cityTEgo * Eigen::Vector3d(p.x, p.y, p.z);
      const double g = ground.bilinearAt(c.head<2>());
      if (!std::isnan(g)) dz.push_back(std::abs(c.z() - g));
      inside += raster.contains(c.head<2>());
    }
    ASSERT_GT(dz.size(), 10000u) << "sweep " << i;
    std::nth_element(dz.begin(), dz.begin() + long(dz.size() / 2), dz.end());
    const double median = dz[dz.size() / 2];
    const double insideFraction = double(inside) / double(road);
    EXPECT_LT(median, 0.05) << "sweep " << i;
    EXPECT_GT(insideFraction, 0.98) << "sweep " << i;
    if (i == 0)
      std::printf("[ info ] %zu points, %zu road: median |z - ground| %.4f m, %.2f %% inside the drivable area\n",
                  sweep->points.size(), road, median, 100.0 * insideFraction);
  }
}

void checkLayout(const fs::path& dir, size_t sweeps) {
  const ArgoverseLog log(dir);
  EXPECT_EQ(log.sweepCount(), sweeps);
  EXPECT_TRUE(std::is_sorted(log.sweepTimestamps().begin(), log.sweepTimestamps().end()));
  EXPECT_EQ(std::adjacent_find(log.sweepTimestamps().begin(), log.sweepTimestamps().end()), log.sweepTimestamps().end());
  // Poses at >= 100 Hz covering every sweep.
  const PoseTrajectory& T = log.cityTEgo();
  EXPECT_GE(double(T.size() - 1) / (double(T.endNs() - T.startNs()) * 1e-9), 100.0);
  EXPECT_TRUE(T.covers(log.sweepTimestamps().back() + 100'000'000));
  EXPECT_EQ(log.calibration().count("up_lidar"), 1u);
  EXPECT_EQ(log.calibration().count("down_lidar"), 1u);
  size_t labelFiles = 0;
  for (const auto& e : fs::directory_iterator(dir / "sensors" / "lidar_labels")) labelFiles += e.path().extension() == ".feather";
  EXPECT_EQ(labelFiles, sweeps);
  for (const auto& e : fs::directory_iterator(dir.parent_path()))
    EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos) << "left behind: " << e.path();
  // Sensor like Argoverse's: ~100k returns, 64 lasers, offsets within one period.
  const auto s = log.sweep(0);
  EXPECT_GT(s->points.size(), 70000u);
  EXPECT_LT(s->points.size(), 130000u);
  int maxLaser = 0;
  int32_t lo = INT32_MAX, hi = 0;
  for (const LidarPoint& p : s->points) {
    maxLaser = std::max(maxLaser, int(p.laserNumber));
    lo = std::min(lo, p.offsetNs);
    hi = std::max(hi, p.offsetNs);
  }
  EXPECT_EQ(maxLaser, 63);
  EXPECT_GE(lo, 0);
  EXPECT_LT(hi, 100'000'000);
  EXPECT_GT(hi, 95'000'000);
}

TEST(SimLog, RealMapAndPosesReadBackWithGroundTruthRoadPoints) {
  SimulationOptions o;
  o.mapLog = test::sharedLog();
  o.trajectory = SimTrajectory::Real;
  o.seconds = 0.6;
  o.outDir = test::freshOutputDir("sim_real");
  const SimulationResult r = simulateLog(o);
  EXPECT_EQ(r.sweeps, 6u);
  checkLayout(r.dir, 6);
  checkRoadPoints(r.dir, 5);
  // The ego follows the real log's poses exactly.
  const ArgoverseLog real(test::sharedLog()), sim(r.dir);
  const int64_t t = sim.sweepTimestamps()[3];
  EXPECT_LT((real.cityTEgo().at(t).matrix() - sim.cityTEgo().at(t).matrix()).norm(), 1e-9);
}

TEST(SimLog, TownRouteReadsBackWithGroundTruthRoadPoints) {
  SimulationOptions o;
  o.townSeed = 3;
  o.seconds = 0.5;
  o.seed = 4;
  o.outDir = test::freshOutputDir("sim_town");
  const SimulationResult r = simulateLog(o);
  checkLayout(r.dir, 5);
  checkRoadPoints(r.dir, 5);
  const ArgoverseLog log(r.dir);
  // Both lidars turn clockwise from the measured Argoverse start azimuths (140 and -40 deg).
  const auto sweep = log.sweep(0);
  for (int unit = 0; unit < 2; ++unit) {
    const Eigen::Vector3d sensor = log.calibration().at(unit == 0 ? "up_lidar" : "down_lidar").translation();
    Eigen::Vector2d first = Eigen::Vector2d::Zero(), last = Eigen::Vector2d::Zero();
    for (const LidarPoint& p : sweep->points) {
      if ((p.laserNumber >= 32) != (unit == 1) || p.offsetNs > 2'000'000 && p.offsetNs < 98'000'000) continue;
      const double a = std::atan2(p.y - sensor.y(), p.x - sensor.x());
      (p.offsetNs <= 2'000'000 ? first : last) += Eigen::Vector2d(std::cos(a), std::sin(a));
    }
    const double a0 = std::atan2(first.y(), first.x()) * 180 / M_PI, a1 = std::atan2(last.y(), last.x()) * 180 / M_PI;
    EXPECT_NEAR(std::remainder(a0 - (unit == 0 ? 136.4 : -43.6), 360.0), 0.0, 3.0) << "unit " << unit;
    EXPECT_NEAR(std::remainder(a1 - a0, 360.0), 7.2, 3.0) << "unit " << unit;  // clockwise: -352.8 = +7.2
  }
  // Route drive: z is the ground height plus the ego origin's 0.32 m.
  const GroundHeight ground = readGroundHeight(log.mapFiles().groundHeight, log.mapFiles().sim2);
  for (size_t i = 0; i < log.cityTEgo().size(); i += 10) {
    const Eigen::Vector3d p = log.cityTEgo().poses()[i].translation();
    EXPECT_NEAR(p.z(), ground.bilinearAt(p.head<2>()) + 0.32, 1e-6);
  }
}

TEST(SimLog, MapChangeRecordsEveryDifference) {
  SimulationOptions o;
  o.mapLog = test::sharedLog();
  o.trajectory = SimTrajectory::Real;
  o.seconds = 0.1;
  o.mapChange = 0.4;
  o.seed = 11;
  o.outDir = test::freshOutputDir("sim_change");
  const SimulationResult r = simulateLog(o);
  const ArgoverseLog log(r.dir), real(test::sharedLog());
  const VectorMap world = readVectorMap(real.mapFiles().vectorMap), written = readVectorMap(log.mapFiles().vectorMap);
  const auto json = nlohmann::json::parse(readFileText(r.dir / "map_change.json"));
  EXPECT_TRUE(json["within_m"].is_null());
  const auto find = [](const VectorMap& m, int64_t id) -> const DrivableArea* {
    for (const DrivableArea& a : m.drivableAreas)
      if (a.id == id) return &a;
    return nullptr;
  };
  size_t removed = 0, added = 0, other = 0, crossings = 0, laneLines = 0;
  for (const auto& c : json["changes"]) {
    const int64_t id = c["id"];
    const std::string kind = c["change"];
    if (c["element"] == "pedestrian_crossing") {
      ++crossings;
      continue;
    }
    if (c["element"] == "lane_boundary") {
      EXPECT_EQ(kind, "lane_line_moved");
      ++laneLines;
      continue;
    }
    if (kind == "removed") {
      EXPECT_TRUE(find(world, id));
      EXPECT_FALSE(find(written, id));
      ++removed;
    } else if (kind == "added") {
      EXPECT_FALSE(find(world, id));
      EXPECT_TRUE(find(written, id));
      ++added;
    } else {
      const DrivableArea *a = find(world, id), *b = find(written, id);
      ASSERT_TRUE(a && b) << kind;
      EXPECT_NE(vectorMapToJson({{*a}, {}, {}}), vectorMapToJson({{*b}, {}, {}})) << kind;
      ++other;
    }
  }
  // The real map's polygons: a share of all of them (no --map-change-within).
  EXPECT_EQ(removed + added + other, size_t(std::llround(0.4 * double(world.drivableAreas.size()))));
  EXPECT_EQ(crossings, std::max<size_t>(1, size_t(std::llround(0.4 * double(world.pedestrianCrossings.size())))));
  EXPECT_EQ(written.drivableAreas.size(), world.drivableAreas.size() - removed + added);
  EXPECT_GE(laneLines, 1u);  // the real map's lanes share their painted lines
  std::printf("[ info ] %zu removed, %zu added, %zu reshaped, %zu crossings, %zu lane lines\n", removed, added, other, crossings, laneLines);
}

// Every file under `dir`, relative path -> bytes.
std::map<std::string, std::vector<uint8_t>> filesUnder(const fs::path& dir) {
  std::map<std::string, std::vector<uint8_t>> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = readFileBytes(e.path());
  return out;
}

TEST(SimCommand, SameCommandTwiceGivesByteIdenticalFiles) {
  const fs::path a = test::freshOutputDir("sim_det_a"), b = test::freshOutputDir("sim_det_b");
  const std::string args = " --seconds 0.3 --seed 9 --parked 0.7 --quiet --map-change 0.2";
  const auto ra = test::runHdprior("sim --town 5 --out '" + a.string() + "'" + args);
  const auto rb = test::runHdprior("sim --town 5 --out '" + b.string() + "'" + args);
  ASSERT_EQ(ra.status, 0) << ra.err;
  ASSERT_EQ(rb.status, 0) << rb.err;
  EXPECT_EQ(ra.out, rb.out);  // the log id
  const auto fa = filesUnder(a), fb = filesUnder(b);
  EXPECT_GT(fa.size(), 3u + 2u * 3u);
  ASSERT_EQ(fa.size(), fb.size());
  for (const auto& [name, bytes] : fa) {
    ASSERT_TRUE(fb.count(name)) << name;
    EXPECT_TRUE(bytes == fb.at(name)) << name << " differs";
  }
  // The log id printed is the folder written.
  std::string id = ra.out;
  while (!id.empty() && (id.back() == '\n' || id.back() == '\r')) id.pop_back();
  EXPECT_TRUE(fs::is_directory(a / id));
}

// One line on stderr naming the problem, exit status 2, the output folder left untouched.
void expectCleanFailure(const std::string& args, const fs::path& out, const std::string& mention) {
  const auto r = test::runHdprior(args);
  EXPECT_EQ(r.status, 2) << args;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  if (fs::is_directory(out)) EXPECT_TRUE(fs::is_empty(out)) << "left behind in " << out;
}

TEST(SimCommand, BadOptionsFailWithOneLineAndLeaveNothing) {
  const fs::path out = test::freshOutputDir("sim_bad");
  const std::string o = " --out '" + out.string() + "' --quiet";
  expectCleanFailure("sim --town 1 --seconds -5" + o, out, "--seconds");
  expectCleanFailure("sim --town 1 --seconds abc" + o, out, "--seconds");
  expectCleanFailure("sim --town 1 --map '" + test::sharedLog().string() + "'" + o, out, "--town");
  expectCleanFailure("sim --out '" + out.string() + "'", out, "--town");
  expectCleanFailure("sim --town 1 --trajectory real" + o, out, "--trajectory");
  expectCleanFailure("sim --town 1 --trajectory fly" + o, out, "--trajectory");
  expectCleanFailure("sim --town 1 --noise -1" + o, out, "--noise");
  expectCleanFailure("sim --town 1 --parked 2" + o, out, "--parked");
  expectCleanFailure("sim --town 1 --map-change 1.5" + o, out, "--map-change");
  expectCleanFailure("sim --town 1 --map-change 0.3 --map-change-within -2" + o, out, "--map-change-within");
  expectCleanFailure("sim --town 1 --map-change 0.3 --map-change-within x" + o, out, "--map-change-within");
  expectCleanFailure("sim --town 1 --map-change-within 15" + o, out, "--map-change-within");
  expectCleanFailure("sim --town 1 --family test" + o, out, "--family");
  expectCleanFailure("sim --town 1 --family tuning --parked 0.2" + o, out, "--parked");
  expectCleanFailure("sim --map /nonexistent/log" + o, out, "/nonexistent/log");
  // Fails after the temporary folder exists (the real log is shorter than 100 s).
  expectCleanFailure("sim --map '" + test::sharedLog().string() + "' --seconds 100" + o, out, "--seconds");
}

TEST(SimCommand, UnwritableOutputFolderFailsCleanly) {
  const fs::path dir = test::freshOutputDir("sim_unwritable");
  std::ofstream(dir / "file") << "x";
  const auto r = test::runHdprior("sim --map '" + test::sharedLog().string() + "' --seconds 0.2 --quiet --out '" +
                                  (dir / "file" / "sub").string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("file/sub"), std::string::npos) << r.err;
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// A folder holding only part of a log: the shared log's map files (in map/, or on their own as
// "Trust, but Verify" ships them), with or without its poses; never sweeps nor calibration.
fs::path partOfTheSharedLog(const std::string& name, bool mapSubfolder, bool poses) {
  const fs::path src = test::sharedLog();
  const fs::path dir = test::freshOutputDir(name) / "in";
  fs::create_directories(dir);
  if (mapSubfolder) {
    fs::create_directory_symlink(src / "map", dir / "map");
  } else {
    for (const auto& e : fs::directory_iterator(src / "map")) fs::create_symlink(e.path(), dir / e.path().filename());
  }
  if (poses) fs::create_symlink(src / "city_SE3_egovehicle.feather", dir / "city_SE3_egovehicle.feather");
  return dir;
}

struct SimRun {
  test::CommandResult result;
  fs::path log;  // the folder written
};

SimRun simulate(const fs::path& in, const std::string& extra = "") {
  const fs::path out = in.parent_path() / "out";
  SimRun r{test::runHdprior("sim --map '" + in.string() + "' --seconds 2 --quiet --out '" + out.string() + "'" + extra), {}};
  std::string id = r.result.out;
  while (!id.empty() && std::isspace((unsigned char)id.back())) id.pop_back();
  r.log = out / id;
  return r;
}

void expectTheDefaultCalibrationNotice(const std::string& err, const fs::path& in) {
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(err.find(in.string() + " has no calibration/egovehicle_SE3_sensor.feather: the simulated lidars have the "
                                   "default Argoverse 2 calibration"), std::string::npos) << err;
}

TEST(SimCommand, MapFilesAloneDriveARouteWithTheDefaultCalibration) {
  for (bool subfolder : {false, true}) {
    const fs::path in = partOfTheSharedLog(subfolder ? "sim_maponly_sub" : "sim_maponly_flat", subfolder, false);
    const SimRun r = simulate(in);
    ASSERT_EQ(r.result.status, 0) << r.result.err;
    expectTheDefaultCalibrationNotice(r.result.err, in);
    const auto info = test::runHdprior("info '" + r.log.string() + "'");
    ASSERT_EQ(info.status, 0) << info.err;
    EXPECT_NE(info.out.find("sweeps:            20"), std::string::npos) << info.out;
    const ArgoverseLog log(r.log);
    EXPECT_EQ(log.city(), "PIT");
    EXPECT_EQ(log.calibration().count("up_lidar"), 1u);
    // A route on the map, not the log's own drive (which it does not have).
    const ArgoverseLog shared(test::sharedLog());
    EXPECT_GT((log.cityTEgo().poses().front().translation() - shared.cityTEgo().poses().front().translation()).norm(), 1.0);
  }
}

TEST(SimCommand, MapAndPosesDriveTheLogsOwnTrajectory) {
  const fs::path in = partOfTheSharedLog("sim_mapposes", true, true);
  const SimRun r = simulate(in);
  ASSERT_EQ(r.result.status, 0) << r.result.err;
  expectTheDefaultCalibrationNotice(r.result.err, in);
  ASSERT_EQ(test::runHdprior("info '" + r.log.string() + "'").status, 0);
  const ArgoverseLog log(r.log), shared(test::sharedLog());
  EXPECT_EQ(log.sweepCount(), 20u);
  const int64_t t = log.sweepTimestamps()[10];
  EXPECT_LT((log.cityTEgo().at(t).translation() - shared.cityTEgo().at(t).translation()).norm(), 1e-6);
}

TEST(SimCommand, AWholeLogNeedsNoNoticeAndAMapAloneHasNoRealTrajectory) {
  const fs::path out = test::freshOutputDir("sim_whole_log");
  const auto whole = test::runHdprior("sim --map '" + test::sharedLog().string() + "' --seconds 0.2 --quiet --out '" +
                                      out.string() + "'");
  ASSERT_EQ(whole.status, 0) << whole.err;
  EXPECT_TRUE(whole.err.empty()) << whole.err;
  const fs::path in = partOfTheSharedLog("sim_maponly_real", true, false);
  expectCleanFailure("sim --map '" + in.string() + "' --trajectory real --quiet --out '" + (in.parent_path() / "out").string() + "'",
                     in.parent_path() / "out", in.string() + "/city_SE3_egovehicle.feather: not found");
}

TEST(SimCommand, MapWithoutDrivableAreasFailsCleanly) {
  // A copy of the real log whose vector map has no drivable areas.
  const fs::path dir = test::freshOutputDir("sim_nodrivable");
  const fs::path log = dir / "log";
  fs::copy(test::sharedLog(), log, fs::copy_options::recursive);
  const ArgoverseLog copy(log);
  VectorMap map = readVectorMap(copy.mapFiles().vectorMap);
  map.drivableAreas.clear();
  writeFileAtomically(copy.mapFiles().vectorMap, vectorMapToJson(map));
  const fs::path out = dir / "out";
  expectCleanFailure("sim --map '" + log.string() + "' --quiet --out '" + out.string() + "'", out, "no drivable areas");
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace hdprior
