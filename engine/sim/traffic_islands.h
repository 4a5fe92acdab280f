#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/map/boundary_distance.h"
#include "engine/map/lane_graph.h"
#include "engine/sim/roadside.h"

namespace hdprior {

// Raised islands and median strips where the drivable area is wide, inside the map's drivable
// polygons (which paint over them): capsules 0.8-2 m wide and 6-24 m long along the nearest
// lane, their edges at least 1 m from the map's boundary, 1.5 m from every lane's centre line
// and 3 m from `egoPath` (samples at most 2 m apart), 30 m apart. Each candidate spot in
// [lo, hi] is kept with probability `density`. Deterministic in `seed`.
std::vector<TrafficIsland> placeTrafficIslands(const BoundaryDistance& mapDistance, const LaneGraph& lanes,
                                               std::span<const Eigen::Vector2d> egoPath, const Eigen::Vector2d& lo,
                                               const Eigen::Vector2d& hi, double density, uint64_t seed);

}  // namespace hdprior
