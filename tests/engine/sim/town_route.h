// A procedural town and a route driven through it (no sweeps): what tests of the world and the
// written map start from.
#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/map/ground_height.h"
#include "engine/map/lane_graph.h"
#include "engine/sim/town_generator.h"
#include "engine/sim/trajectory.h"

namespace hdprior::test {

struct TownRoute {
  TownMap town;
  GroundHeight ground;
  LaneGraph lanes;
  PoseTrajectory route;
  std::vector<Eigen::Vector2d> path;  // the route's poses on the map plane

  TownRoute(uint64_t townSeed, uint64_t routeSeed, double seconds)
      : town(generateTown(TownOptions{}, townSeed)),
        ground(GroundHeight::fromNpy(town.groundHeight, town.imgSim2City, "town")),
        lanes(town.vectorMap, {}, "town") {
    RouteOptions ro;
    ro.seconds = seconds;
    route = routeTrajectory(lanes, ground, ro, routeSeed);
    for (const SE3& p : route.poses()) path.push_back(p.translation().head<2>());
  }
};

}  // namespace hdprior::test
