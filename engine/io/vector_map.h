#pragma once
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace hdprior {

using Polyline3 = std::vector<Eigen::Vector3d>;

struct DrivableArea {
  int64_t id = 0;
  Polyline3 areaBoundary;  // closed polygon, city frame, at least 3 vertices
};

struct LaneSegment {
  int64_t id = 0;
  bool isIntersection = false;
  std::string laneType;  // VEHICLE, BIKE, BUS
  Polyline3 leftLaneBoundary, rightLaneBoundary;
  std::string leftLaneMarkType, rightLaneMarkType;
  std::vector<int64_t> successors, predecessors;
  std::optional<int64_t> leftNeighborId, rightNeighborId;
};

struct PedestrianCrossing {
  int64_t id = 0;
  Polyline3 edge1, edge2;  // two points each
};

// Whether a lane boundary's mark type is painted on the road (not NONE or UNKNOWN).
inline bool isPaintedMark(const std::string& markType) {
  return !markType.empty() && markType != "NONE" && markType != "UNKNOWN";
}

// A boundary two lanes share (one's left, the other's right, maybe reversed) is one line: its key
// is its end points to a decimetre, in a fixed order.
using LaneLineKey = std::tuple<long, long, long, long>;
inline LaneLineKey laneLineKey(const Polyline3& line) {
  auto a = std::make_pair(std::lround(line.front().x() * 10), std::lround(line.front().y() * 10));
  auto b = std::make_pair(std::lround(line.back().x() * 10), std::lround(line.back().y() * 10));
  if (b < a) std::swap(a, b);
  return {a.first, a.second, b.first, b.second};
}

// The Argoverse 2 vector map (log_map_archive_*.json), each list sorted by id.
struct VectorMap {
  std::vector<DrivableArea> drivableAreas;
  std::vector<LaneSegment> laneSegments;
  std::vector<PedestrianCrossing> pedestrianCrossings;
};

// Strict: missing or mistyped members, non-finite coordinates and drivable areas with
// fewer than 3 vertices throw Error naming the source and the element.
VectorMap parseVectorMap(const std::string& json, const std::string& source);
VectorMap readVectorMap(const std::filesystem::path& path);
std::string vectorMapToJson(const VectorMap& map);

}  // namespace hdprior
