#pragma once
#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "engine/io/vector_map.h"

namespace hdprior {

struct LaneGraphOptions {
  double centerlineSpacing = 1.0;  // metres between centerline points (at most)
};

// A lane segment of the lane graph; links are indices into LaneGraph::lanes().
struct Lane {
  int64_t id = 0;
  bool isIntersection = false;
  std::string laneType;
  Polyline3 centerline;  // in the direction of travel
  double length = 0.0;   // of the centerline, metres
  std::vector<size_t> successors, predecessors;
  std::optional<size_t> leftNeighbor, rightNeighbor;
};

// Both polylines resampled to n points evenly spaced by arc length (n >= 2).
Polyline3 resampleByArcLength(const Polyline3& line, size_t n);
// The mean of the left and right boundaries after resampling both to the same number of
// points, enough for at most `spacing` metres between points along the longer one.
Polyline3 laneCenterline(const Polyline3& left, const Polyline3& right, double spacing);
double polylineLength(const Polyline3& line);

// The lane graph of a vector map: lanes with centerlines, successor and predecessor links,
// and route walking for the simulator. Links to lane ids outside the map (a log's map is
// cropped) are dropped and counted.
class LaneGraph {
 public:
  LaneGraph() = default;
  // Throws Error(source, ...) for a lane with an empty boundary or bad options.
  LaneGraph(const VectorMap& map, const LaneGraphOptions& options, const std::string& source);

  const std::vector<Lane>& lanes() const { return lanes_; }
  std::optional<size_t> indexOf(int64_t id) const;
  size_t droppedLinks() const { return droppedLinks_; }

  // Lanes reachable from `from` along successors (including `from`), ascending indices.
  std::vector<size_t> reachable(size_t from) const;
  // The route of least centerline length from `from` to `to` (both included), following
  // successors; nullopt if `to` is not reachable. Length counts every lane but the last.
  std::optional<std::vector<size_t>> shortestRoute(size_t from, size_t to) const;
  // Walks successors from `start`, picking uniformly at random, until the route's length
  // reaches minLength or a lane has no successor.
  std::vector<size_t> randomRoute(size_t start, double minLength, std::mt19937_64& rng) const;
  // The centerlines of a route joined into one polyline (shared end points once).
  Polyline3 routeCenterline(std::span<const size_t> route) const;
  // The lane whose centerline passes closest to `city` (2-D), if within maxDistance.
  std::optional<size_t> nearestLane(const Eigen::Vector2d& city, double maxDistance) const;

 private:
  std::vector<Lane> lanes_;
  std::unordered_map<int64_t, size_t> index_;
  size_t droppedLinks_ = 0;
};

}  // namespace hdprior
