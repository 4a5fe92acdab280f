#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
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
