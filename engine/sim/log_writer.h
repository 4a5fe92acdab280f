#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "engine/sim/scene_builder.h"
#include "engine/sim/scene_variation.h"
#include "engine/sim/sweep_simulator.h"
#include "engine/sim/town_options.h"
#include "engine/sim/trajectory.h"

namespace hdprior {

enum class SimTrajectory { Real, Route };

// What `hdprior sim` does, as one value.
struct SimulationOptions {
  std::optional<uint64_t> townSeed;     // a procedural town, or
  std::filesystem::path mapLog;         // a real log's folder (openMapFolder): its map, and for Real its
                                        // poses; sweeps and calibration are not needed
  std::filesystem::path outDir;
  double seconds = 0.0;                 // <= 0: 20 s for a route, the whole log for Real
  uint64_t seed = 0;                    // scene, route, noise
  SimTrajectory trajectory = SimTrajectory::Route;
  SweepNoise noise;
  double mapChange = 0.0;               // share of the drivable polygons and crossings changed in the
                                        // written map (changeMap)
  std::optional<double> mapChangeWithin;  // only elements whose outline passes this near the drive (metres)
  std::optional<SceneFamily> family;    // the scene varied by drawSceneVariation(family, seed); it
                                        // sets town, scene (parked included) and lidar errors
  int threads = 2;
  TownOptions town;
  SceneOptions scene;
  RouteOptions route;
  std::function<void(size_t done, size_t total)> progress;  // called from the calling thread
};

struct SimulationResult {
  std::string logId;
  std::filesystem::path dir;  // outDir / logId
  size_t sweeps = 0;
};

// Simulates a drive and writes outDir/<log id>/ in the Argoverse 2 layout:
//   sensors/lidar/<ts>.feather (LZ4, float16 x y z, intensity, laser_number, offset_ns),
//   sensors/lidar_labels/<ts>.feather (one uint8 column "label": PointLabel per point, same rows),
//   city_SE3_egovehicle.feather (>= 100 Hz), calibration/egovehicle_SE3_sensor.feather,
//   map/ (the world's map, or the changed one), map_change.json when mapChange > 0 (the changes,
//   labelled: mapChangesToJson),
//   scene_variation.json with a family (the calibration written is the believed one).
// Everything is written into a temporary folder beside it and renamed at the end; on any
// error nothing is left. The log id is a UUID derived from the options, so the same options
// give byte-identical output. Throws Error naming the option or file that is wrong.
SimulationResult simulateLog(const SimulationOptions& options);

}  // namespace hdprior
