#pragma once
#include <cstdint>
#include <optional>
#include <span>

#include <Eigen/Core>

#include "engine/io/vector_map.h"
#include "engine/map/ground_height.h"
#include "engine/map/lane_graph.h"
#include "engine/sim/scene.h"

namespace hdprior {

struct SceneOptions {
  double margin = 120.0;           // world built this far around the drive, metres
  double rasterResolution = 0.1;   // of the curb (drivable boundary) distance field
  double sidewalkWidth = 4.0;      // metres beyond the curb labelled sidewalk
  double parked = 0.5;             // fraction of kerbside parking slots holding a car
  double buildingDensity = 0.75;   // fraction of facade slots holding a building (rest are gaps)
  double treeDensity = 0.35;       // fraction of sidewalk slots with a tree
  double poleSpacing = 30.0;       // metres between poles along a curb
  int movingCars = 30;
  // Scene families (engine/sim/scene_variation.h); the defaults leave today's scenes as they were.
  double buildingDensityVariation = 0.0;  // the density swings by up to this fraction of itself (open stretches)
  double vegetationDensity = 0.0;  // fraction of sidewalk slots with a bush or hedge (and island planters)
  double islandDensity = 0.0;      // of candidate spots for a traffic island (needs a roadside)
  std::optional<RoadsideOptions> roadside;  // physical kerbs, sidewalks, map error; nullopt: plain kerbs
};

// Builds the world around a drive: the ground from the map's ground height (NaN filled
// from the nearest valid pixel), curbs along the drivable area's boundary, and objects
// placed along it, none within 2.5 m of `egoPath` (so the ego vehicle never drives through
// them). With options.roadside, the kerbs are shaped (and moved off the map) by it and traffic
// islands are raised inside wide drivable areas. Deterministic in `seed`. Throws Error(source, ...) if no drivable area is near.
Scene buildScene(const VectorMap& world, const GroundHeight& ground, const LaneGraph& lanes,
                 std::span<const Eigen::Vector2d> egoPath, int64_t startNs, const SceneOptions& options,
                 uint64_t seed, const std::string& source);

}  // namespace hdprior
