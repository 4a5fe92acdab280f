#pragma once
#include <cstdint>

#include "engine/geom/pose_trajectory.h"
#include "engine/map/ground_height.h"
#include "engine/map/lane_graph.h"

namespace hdprior {

// A drive along the lane graph: cruise speed, slower in turns (lateral acceleration bound),
// stops at some junction entries, acceleration-limited in between.
struct RouteOptions {
  double seconds = 20.0;
  double cruiseSpeed = 8.0;        // m/s
  double lateralAccel = 2.0;       // m/s^2 in turns
  double accel = 1.5;              // m/s^2, speeding up and braking
  double stopProbability = 0.35;   // per junction entered
  double stopSeconds = 2.0;
  double poseRateHz = 200.0;
  double egoHeight = 0.32;         // ego origin above the ground (measured on real logs)
  int64_t startNs = 1'700'000'000'000'000'000;
};

// Poses city_T_ego at poseRateHz from startNs for `seconds` (+ one sweep period of margin):
// x, y on the lane centerlines of a random route (by seed), yaw along it, z = ground height
// + egoHeight, roll and pitch from the ground's slope. Throws Error if no route is long
// enough or the ground height is missing under it.
PoseTrajectory routeTrajectory(const LaneGraph& lanes, const GroundHeight& ground, const RouteOptions& options,
                               uint64_t seed);

// The part of `poses` from its start for `seconds` (all of it if seconds <= 0), with an
// interpolated end pose. Throws Error if the poses do not span that long.
PoseTrajectory cropTrajectory(const PoseTrajectory& poses, double seconds);

}  // namespace hdprior
