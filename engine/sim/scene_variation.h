#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/sim/lidar_model.h"
#include "engine/sim/roadside.h"
#include "engine/sim/scene_builder.h"
#include "engine/sim/town_options.h"

namespace hdprior {

// Scene families: worlds to develop against. Seeds of the tuning family shape the worlds a
// matcher is tuned on; the validation family draws from the same ranges with another stream,
// so no validation world is ever seen while tuning.
enum class SceneFamily { Tuning, Validation };
const char* familyName(SceneFamily family);  // "tuning", "validation"
// Throws Error("option --family", ...) for any other name.
SceneFamily parseSceneFamily(const std::string& name);

// Everything a family draws for one log. Default-constructed it is neutral: applying it
// changes nothing, so scenes, logs and their ids stay what they were before families.
struct SceneVariation {
  std::optional<SceneFamily> family;  // nullopt: neutral
  uint64_t seed = 0;
  // Procedural towns: wider multi-lane streets (three lanes per direction from 21 m) and
  // larger junctions.
  double minRoadWidth = 6.0, maxRoadWidth = 20.0, junctionMargin = 4.0;
  // Objects.
  double parked = 0.5, buildingDensity = 0.75, buildingDensityVariation = 0.0, treeDensity = 0.35;
  double vegetationDensity = 0.0, islandDensity = 0.0;
  // The physical roadside (kerbs, gutters, camber, sidewalks, verge, map error).
  RoadsideOptions roadside;
  // The lidar, per laser number (0-31 up_lidar, 32-63 down_lidar): how far above its
  // calibrated elevation each laser fires (radians) and its range bias (metres); how far the
  // down lidar's true mounting is from the calibration written (rotation vector, radians, and
  // translation, metres, in the calibrated sensor frame).
  std::vector<double> elevationErrors, rangeBiases;
  Eigen::Vector3d downRotationError = Eigen::Vector3d::Zero(), downTranslationError = Eigen::Vector3d::Zero();

  bool neutral() const { return !family; }
  void applyTo(TownOptions& town) const;
  void applyTo(SceneOptions& scene) const;
  void applyTo(LidarModel& lidar) const;
};

// The variation of seed `seed` in `family`, deterministic. Ranges (per log; "varying" ones
// vary smoothly along the streets): kerb height 0-0.25 m varying, with 0-30 % verge without
// kerb, 0-50 % mountable kerbs rising over 0.3-0.6 m, kerb cuts of 3-6 m every 25-80 m; gutters
// 0.3-0.5 m wide and 2-5 cm deep; camber 1-3 % up to 2.5-5 m in; sidewalks 2-6 m wide varying
// with a 1-4 % cross slope, verge relief 2-8 cm; map error 0-0.3 m over 20-80 m; parked cars
// 0-90 %; buildings 0.1-0.8 swinging by 0-80 %; trees 0.1-0.5; bushes and hedges 0.1-0.6;
// islands 0-0.5; paint 1.4-2x the road's reflectivity, 10-40 % worn, bright asphalt (2-3x) on
// 3-7 % of the road in patches and 6-12 % in flecks; towns' streets 6-9 .. 18-30 m wide, junction margin 4-10 m; lidar elevation
// errors up to 0-0.2 deg and range biases up to 0-3 cm per laser, the down lidar's mounting
// 0-0.3 deg and 0-2 cm off its calibration.
SceneVariation drawSceneVariation(SceneFamily family, uint64_t seed);

// The variation as JSON (degrees for angles), written as scene_variation.json beside a log.
std::string sceneVariationToJson(const SceneVariation& variation);

}  // namespace hdprior
