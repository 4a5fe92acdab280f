#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/io/vector_map.h"

namespace hdprior {

// One difference between the written map and the world that was ray-cast.
struct DrivableAreaChange {
  enum class Kind { Removed, Shifted, Added };
  Kind kind = Kind::Removed;
  int64_t id = 0;                                     // the polygon's id (new id for Added)
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();    // Shifted: metres, city frame
};

struct ChangedMap {
  VectorMap map;
  std::vector<DrivableAreaChange> changes;
};

// The TbV theme: a map that is out of date. round(fraction * N) of the N drivable polygons
// (chosen by seed) are removed, shifted by 1-3 m, or get a new drivable polygon added beside
// them (a 8 m x 15 m strip reaching outwards from one of its vertices). Lanes and crossings
// are kept. Throws Error for a fraction outside [0, 1].
ChangedMap changeDrivableAreas(const VectorMap& world, double fraction, uint64_t seed);
// {"fraction": F, "changes": [{"drivable_area_id": id, "change": "removed|shifted|added",
// "shift_m": [dx, dy]}]}
std::string mapChangesToJson(double fraction, const std::vector<DrivableAreaChange>& changes);

}  // namespace hdprior
