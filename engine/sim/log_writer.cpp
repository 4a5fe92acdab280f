#include "engine/sim/log_writer.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <mutex>
#include <sstream>
#include <system_error>
#include <thread>

#include "engine/error.h"
#include "engine/io/arrow_table.h"
#include "engine/io/ego_poses.h"
#include "engine/io/feather.h"
#include "engine/io/file_bytes.h"
#include "engine/io/lidar_sweep.h"
#include "engine/io/map_folder.h"
#include "engine/io/partial_folder.h"
#include "engine/io/vector_map.h"
#include "engine/map/lane_graph.h"
#include "engine/sim/lidar_model.h"
#include "engine/sim/map_change.h"
#include "engine/sim/town_generator.h"
#include "engine/sim/town_writer.h"
#include "engine/sim/splitmix.h"

namespace hdprior {
namespace fs = std::filesystem;
namespace {

uint64_t hashText(const std::string& s, uint64_t h) {
  for (unsigned char c : s) h = splitmix(h ^ c);
  return h;
}

// A UUID-shaped id (version-4 layout) derived from everything that shapes the output.
std::string logIdFor(const SimulationOptions& o, const std::string& source) {
  std::ostringstream key;
  key.precision(17);
  key << "hdprior-sim-v1|" << source << '|' << o.seconds << '|' << o.seed << '|' << int(o.trajectory) << '|'
      << o.noise.rangeSigma << '|' << o.noise.dropout << '|' << o.scene.parked << '|' << o.mapChange;
  if (o.family) key << "|family " << familyName(*o.family);  // only then: ids without a family stay
  if (o.mapChangeWithin) key << "|within " << *o.mapChangeWithin;
  const uint64_t a = hashText(key.str(), 1), b = hashText(key.str(), 2);
  char buf[40];
  std::snprintf(buf, sizeof buf, "%08x-%04x-4%03x-%04x-%012llx", unsigned(a >> 32), unsigned((a >> 16) & 0xffff),
                unsigned(a & 0xfff), unsigned(0x8000 | ((b >> 48) & 0x3fff)),
                (unsigned long long)(b & 0xffffffffffffULL));
  return buf;
}

void check(bool ok, const std::string& option, const std::string& reason) {
  if (!ok) throw Error("option " + option, reason);
}

void makeDirs(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) throw Error(dir.string(), "cannot create directory" + (ec ? ": " + ec.message() : ""));
}

// The world a drive is simulated in: its map and where it comes from.
struct World {
  VectorMap map;
  GroundHeight ground;
  std::string source, city;
  std::optional<TownMap> town;
  std::optional<MapFolder> folder;  // a real log's map
  PoseTrajectory logPoses;          // its poses, for SimTrajectory::Real
};

World loadWorld(const SimulationOptions& o, const TownOptions& town) {
  World w;
  if (o.townSeed) {
    w.town = generateTown(town, *o.townSeed);
    w.map = w.town->vectorMap;
    w.ground = GroundHeight::fromNpy(w.town->groundHeight, w.town->imgSim2City, "town");
    w.source = "town " + std::to_string(*o.townSeed);
    w.city = "SIM";
  } else {
    w.folder = openMapFolder(o.mapLog);
    w.map = readVectorMap(w.folder->files.vectorMap);
    w.source = w.folder->files.vectorMap.string();
    if (w.map.drivableAreas.empty()) throw Error(w.source, "map has no drivable areas");
    w.ground = readGroundHeight(w.folder->files.groundHeight, w.folder->files.sim2);
    w.city = w.folder->city;
    if (o.trajectory == SimTrajectory::Real) {
      if (!w.folder->poses) {
        throw Error((o.mapLog / "city_SE3_egovehicle.feather").string(),
                    "not found: --trajectory real follows the log's poses (--trajectory route drives the map alone)");
      }
      w.logPoses = readEgoPoses(*w.folder->poses);
    }
  }
  return w;
}

void writeMap(const World& w, const VectorMap& written, bool changed, const fs::path& dir, const std::string& logId) {
  if (w.town) {
    TownMap copy = *w.town;
    copy.vectorMap = written;
    writeTownMap(dir, logId, w.city, copy);
    return;
  }
  const LogMapFiles& files = w.folder->files;
  const std::string name = files.vectorMap.filename().string();
  const size_t cityAt = name.find("_city_");
  const std::string suffix = cityAt == std::string::npos ? "_city_0.json" : name.substr(cityAt);
  const fs::path mapDir = dir / "map";
  makeDirs(mapDir);
  const fs::path vm = mapDir / ("log_map_archive_" + logId + "____" + w.city + suffix);
  if (changed) writeFileAtomically(vm, vectorMapToJson(written));
  else writeFileAtomically(vm, readFileBytes(files.vectorMap));
  writeFileAtomically(mapDir / (logId + "_ground_height_surface____" + w.city + ".npy"), readFileBytes(files.groundHeight));
  writeFileAtomically(mapDir / (logId + "___img_Sim2_city.json"), readFileBytes(files.sim2));
}

void writeLabels(const fs::path& path, const std::vector<uint8_t>& labels) {
  arrow::Table table;
  table.numRows = int64_t(labels.size());
  table.columns.push_back(arrow::Column::fromValues<uint8_t>("label", arrow::Type::UInt8, labels));
  arrow::writeFeather(path, table);
}

}  // namespace

SimulationResult simulateLog(const SimulationOptions& o) {
  check(o.townSeed.has_value() != !o.mapLog.empty(), "--town/--map", "give exactly one of --town SEED and --map LOG");
  check(o.seconds >= 0.0 && std::isfinite(o.seconds), "--seconds", "must be positive");
  check(o.noise.rangeSigma >= 0.0 && o.noise.rangeSigma < 10.0, "--noise", "must be between 0 and 10 m");
  check(o.noise.dropout >= 0.0 && o.noise.dropout < 1.0, "--dropout", "must be in [0, 1)");
  check(o.scene.parked >= 0.0 && o.scene.parked <= 1.0, "--parked", "must be between 0 and 1");
  check(o.mapChange >= 0.0 && o.mapChange <= 1.0, "--map-change", "must be between 0 and 1");
  check(!o.mapChangeWithin || (*o.mapChangeWithin >= 0.0 && std::isfinite(*o.mapChangeWithin)), "--map-change-within",
        "must be a distance of at least 0 m");
  check(!o.mapChangeWithin || o.mapChange > 0.0, "--map-change-within", "needs --map-change F (F > 0)");
  check(o.threads >= 1, "--threads", "must be at least 1");
  check(o.trajectory == SimTrajectory::Route || !o.mapLog.empty(), "--trajectory",
        "real needs a real log (--map LOG)");
  check(!o.outDir.empty(), "--out", "missing output folder");

  const SceneVariation variation = o.family ? drawSceneVariation(*o.family, o.seed) : SceneVariation{};
  TownOptions townOptions = o.town;
  SceneOptions sceneOptions = o.scene;
  variation.applyTo(townOptions);
  variation.applyTo(sceneOptions);
  const World world = loadWorld(o, townOptions);
  // Output folder first (fails fast when it cannot be written), under a temporary name.
  const std::string source = o.townSeed ? world.source : world.folder->id;
  const std::string logId = logIdFor(o, source);
  makeDirs(o.outDir);
  PartialFolder temp(o.outDir / logId);
  makeDirs(temp.path() / "sensors" / "lidar");
  makeDirs(temp.path() / "sensors" / "lidar_labels");
  makeDirs(temp.path() / "calibration");

  const LaneGraph lanes(world.map, {}, world.source);
  LidarModel lidar = argoverseLikeLidar();
  variation.applyTo(lidar);  // errors to ray-cast with; its calibration() is the one written

  // The drive.
  PoseTrajectory cityTEgo;
  if (o.trajectory == SimTrajectory::Route) {
    RouteOptions ro = o.route;
    ro.seconds = o.seconds > 0.0 ? o.seconds : 20.0;
    cityTEgo = routeTrajectory(lanes, world.ground, ro, o.seed);
  } else {
    cityTEgo = cropTrajectory(world.logPoses, o.seconds);
  }
  const int64_t period = lidar.periodNs;
  const size_t sweeps = o.seconds > 0.0 ? size_t(std::llround(o.seconds * 1e9 / double(period)))
                                        : size_t((cityTEgo.endNs() - cityTEgo.startNs()) / period) - 1;
  check(sweeps >= 1, "--seconds", "too short for one sweep (0.1 s)");
  std::vector<int64_t> sweepNs(sweeps);
  for (size_t k = 0; k < sweeps; ++k) sweepNs[k] = cityTEgo.startNs() + int64_t(k) * period;

  std::vector<Eigen::Vector2d> path;
  for (const SE3& p : cityTEgo.poses()) path.push_back(p.translation().head<2>());
  const Scene scene =
      buildScene(world.map, world.ground, lanes, path, cityTEgo.startNs(), sceneOptions, o.seed, world.source);
  const MapChangeOptions change{o.mapChange, o.mapChangeWithin};
  const ChangedMap written = changeMap(world.map, change, path, o.seed);

  writeMap(world, written.map, o.mapChange > 0.0, temp.path(), logId);
  if (o.mapChange > 0.0) writeFileAtomically(temp.path() / "map_change.json", mapChangesToJson(change, written.changes));
  if (o.family) writeFileAtomically(temp.path() / "scene_variation.json", sceneVariationToJson(variation));
  writeEgoPoses(temp.path() / "city_SE3_egovehicle.feather", cityTEgo);
  writeSensorCalibration(temp.path() / "calibration" / "egovehicle_SE3_sensor.feather", lidar.calibration());

  // Sweeps in parallel; each is a function of its index only, so the output is deterministic.
  std::atomic<size_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex errorMutex;
  const auto worker = [&] {
    try {
      for (size_t k = next++; k < sweeps && !failed; k = next++) {
        const SimulatedSweep s =
            simulateSweep(scene, lidar, cityTEgo, sweepNs[k], o.noise, splitmix(o.seed ^ splitmix(k + 1)));
        const std::string name = std::to_string(sweepNs[k]) + ".feather";
        writeLidarSweep(temp.path() / "sensors" / "lidar" / name, s.sweep);
        writeLabels(temp.path() / "sensors" / "lidar_labels" / name, s.labels);
        ++done;
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(errorMutex);
      if (!error) error = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < o.threads; ++t) pool.emplace_back(worker);
  if (o.progress) {
    std::thread main(worker);
    size_t shown = size_t(-1);
    while (done < sweeps && !failed) {
      if (done != shown) o.progress(shown = done, sweeps);
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    main.join();
  } else {
    worker();
  }
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  if (o.progress) o.progress(sweeps, sweeps);

  return {logId, temp.publish(), sweeps};
}

}  // namespace hdprior
