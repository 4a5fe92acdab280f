// Scene families end to end: a varied world keeps the drive clear and the islands on the road;
// a log simulated with --family is written, readable and says what its world was; without a
// family the simulator writes exactly what it wrote before families existed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "engine/io/argoverse_log.h"
#include "engine/io/feather.h"
#include "engine/io/file_bytes.h"
#include "engine/io/vector_map.h"
#include "engine/sim/log_writer.h"
#include "engine/sim/scene_builder.h"
#include "engine/sim/scene_variation.h"
#include "engine/sim/town_generator.h"
#include "engine/sim/trajectory.h"
#include "test_data.h"

namespace hdprior {
namespace {
namespace fs = std::filesystem;

double distanceToPath(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& path) {
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& q : path) best = std::min(best, (p - q).norm());
  return best;
}

TEST(SceneFamily, VariedWorldKeepsTheDriveClearAndIslandsOnTheRoad) {
  const SceneVariation v = drawSceneVariation(SceneFamily::Tuning, 5);
  TownOptions townOptions;
  v.applyTo(townOptions);
  const TownMap town = generateTown(townOptions, 7);
  const GroundHeight ground = GroundHeight::fromNpy(town.groundHeight, town.imgSim2City, "town");
  const LaneGraph lanes(town.vectorMap, {}, "town");
  RouteOptions ro;
  ro.seconds = 15.0;
  const PoseTrajectory route = routeTrajectory(lanes, ground, ro, 2);
  std::vector<Eigen::Vector2d> path;
  for (const SE3& T : route.poses()) path.push_back(T.translation().head<2>());
  SceneOptions o;
  v.applyTo(o);
  o.islandDensity = 0.5;
  o.vegetationDensity = 0.5;
  ASSERT_TRUE(o.roadside);
  const Scene scene = buildScene(town.vectorMap, ground, lanes, path, route.startNs(), o, 1, "town");
  ASSERT_TRUE(scene.roadside());
  const auto& islands = scene.roadside()->islands();
  EXPECT_GT(islands.size(), 0u);
  for (const TrafficIsland& t : islands) {
    const Eigen::Vector2d c = 0.5 * (t.a + t.b);
    EXPECT_LT(scene.mapBoundaryDistance(c), -1.0);  // inside the map's drivable area ...
    EXPECT_GT(scene.boundaryDistance(c), 0.3);      // ... but physically not road
    EXPECT_GT(distanceToPath(c, path), t.radius + 2.5);
    EXPECT_GT(distanceToPath(t.a, path), t.radius + 2.5);
    EXPECT_GT(distanceToPath(t.b, path), t.radius + 2.5);
  }
  size_t bushes = 0;
  for (const SceneCylinder& c : scene.cylinders()) {
    EXPECT_GT(distanceToPath(c.centre, path), 2.5);
    bushes += c.radius >= 0.4 && c.zMax - c.zMin <= 1.6 + 1e-9;
  }
  EXPECT_GT(bushes, 5u);
  double lowest = 1.0, highest = 0.0;
  for (size_t i = 0; i < path.size(); i += 20) {
    EXPECT_LT(scene.boundaryDistance(path[i]), 0.0) << i;  // the drive is on the road
    lowest = std::min(lowest, scene.curbHeight(path[i]));
    highest = std::max(highest, scene.curbHeight(path[i]));
  }
  EXPECT_GE(lowest, 0.0);
  EXPECT_LE(highest, v.roadside.kerbHeightMax + 1e-6);
  std::printf("[ info ] %zu islands, %zu bushes, %zu boxes, kerb %.3f-%.3f m\n", islands.size(), bushes,
              scene.boxes().size(), lowest, highest);
}

TEST(SceneFamily, LogWithAFamilyIsWrittenReadableAndSaysWhatItsWorldWas) {
  SimulationOptions o;
  o.townSeed = 3;
  o.seconds = 0.3;
  o.seed = 4;
  o.family = SceneFamily::Validation;
  o.outDir = test::freshOutputDir("sim_family");
  const SimulationResult r = simulateLog(o);
  EXPECT_EQ(r.sweeps, 3u);
  const ArgoverseLog log(r.dir);
  ASSERT_EQ(log.sweepCount(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    const auto sweep = log.sweep(i);
    EXPECT_GT(sweep->points.size(), 50000u);
    const arrow::Table labels =
        arrow::readFeather(r.dir / "sensors" / "lidar_labels" / (std::to_string(sweep->timestampNs) + ".feather"));
    EXPECT_EQ(size_t(labels.numRows), sweep->points.size());
  }
  const SceneVariation v = drawSceneVariation(SceneFamily::Validation, 4);
  const auto json = nlohmann::json::parse(readFileText(r.dir / "scene_variation.json"));
  EXPECT_EQ(json["family"], "validation");
  EXPECT_EQ(json["seed"], 4);
  EXPECT_NEAR(double(json["objects"]["parked"]), v.parked, 1e-12);
  EXPECT_NEAR(double(json["roadside"]["map_error_amplitude_m"]), v.roadside.mapErrorAmplitude, 1e-12);
  EXPECT_EQ(json["lidar"]["elevation_error_deg"].size(), 64u);
  // The calibration written is the nominal one, not the mounting the rays were cast from.
  const SensorCalibration nominal = argoverseLikeLidar().calibration();
  const SE3 written = log.calibration().at("down_lidar");
  EXPECT_LT((written.matrix() - nominal.at("down_lidar").matrix()).norm(), 1e-6);
  LidarModel cast = argoverseLikeLidar();
  v.applyTo(cast);
  const SE3 delta = written.inverse() * *cast.units[1].trueEgoTSensor;
  EXPECT_NEAR(Eigen::AngleAxisd(delta.rotation()).angle(), v.downRotationError.norm(), 1e-6);
  EXPECT_NEAR(delta.translation().norm(), v.downTranslationError.norm(), 1e-6);
  // The map written is the town's own (the kerb's displacement is physical only).
  TownOptions townOptions;
  v.applyTo(townOptions);
  const VectorMap map = readVectorMap(log.mapFiles().vectorMap);
  const TownMap town = generateTown(townOptions, 3);
  ASSERT_EQ(map.drivableAreas.size(), town.vectorMap.drivableAreas.size());
  EXPECT_LT((map.drivableAreas[0].areaBoundary[0] - town.vectorMap.drivableAreas[0].areaBoundary[0]).norm(), 1e-3);
  // The family is part of the log id; the other family gives another log.
  o.family = SceneFamily::Tuning;
  const SimulationResult tuning = simulateLog(o);
  EXPECT_NE(tuning.logId, r.logId);
}

// FNV-1a over every file of a folder (relative path and bytes, in path order).
uint64_t folderHash(const fs::path& dir) {
  std::map<std::string, std::vector<uint8_t>> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = readFileBytes(e.path());
  uint64_t h = 1469598103934665603ULL;
  const auto add = [&](uint8_t b) { h = (h ^ b) * 1099511628211ULL; };
  for (const auto& [name, bytes] : files) {
    for (char c : name) add(uint8_t(c));
    for (uint8_t b : bytes) add(b);
  }
  return h;
}

// Without a family the simulator's output is byte for byte what it was before families (the
// figures were taken with the simulator of main before this change, same build type), but for
// road paint: the hash was taken again when lane lines and crossings were painted, which changed
// only the sweeps' intensities (labels, poses and map byte-identical to before).
TEST(SceneFamily, WithoutAFamilyTheSimulatorWritesWhatItWroteBefore) {
  const fs::path out = test::freshOutputDir("sim_neutral");
  const auto r = test::runHdprior("sim --town 5 --seconds 0.3 --seed 9 --parked 0.7 --quiet --out '" + out.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  std::string id = r.out;
  while (!id.empty() && (id.back() == '\n' || id.back() == '\r')) id.pop_back();
  EXPECT_EQ(id, "4cfb11b7-c0dd-4805-bca6-59079a2eca1e");
  EXPECT_EQ(folderHash(out / id), 0x2f4fa0b5ea441921ULL) << std::hex << folderHash(out / id);
}

}  // namespace
}  // namespace hdprior
