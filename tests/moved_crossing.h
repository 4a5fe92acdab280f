// A simulated log's map with one crossing moved: the crossing nearest to the drive (a painted one
// the drive passes over) removed, and a crossing 3 m deep drawn across the road, with no paint, at
// the pose farthest from every crossing. A stale map for the crossing check.
#pragma once
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <utility>

#include "engine/error.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/file_bytes.h"
#include "engine/io/vector_map.h"

namespace hdprior::test {

inline Eigen::Vector2d crossingCentre(const PedestrianCrossing& c) {
  return (c.edge1.front() + c.edge1.back() + c.edge2.front() + c.edge2.back()).head<2>() / 4.0;
}

inline double distanceToDrive(const Eigen::Vector2d& p, const PoseTrajectory& drive) {
  double best = 1e9;
  for (const SE3& pose : drive.poses()) best = std::min(best, (pose.translation().head<2>() - p).norm());
  return best;
}

// Returns the removed crossing's centre and the drawn crossing's id.
inline std::pair<Eigen::Vector2d, int64_t> moveACrossing(const std::filesystem::path& log) {
  const ArgoverseLog opened(log);
  const PoseTrajectory drive = opened.cityTEgoAtSweeps();
  VectorMap map = readVectorMap(opened.mapFiles().vectorMap);
  auto nearest = std::min_element(map.pedestrianCrossings.begin(), map.pedestrianCrossings.end(), [&](const auto& a, const auto& b) {
    return distanceToDrive(crossingCentre(a), drive) < distanceToDrive(crossingCentre(b), drive);
  });
  if (nearest == map.pedestrianCrossings.end() || distanceToDrive(crossingCentre(*nearest), drive) > 5.0)
    throw Error(log.string(), "the drive passes over no crossing");
  const Eigen::Vector2d removed = crossingCentre(*nearest);
  map.pedestrianCrossings.erase(nearest);
  const SE3 far = *std::max_element(drive.poses().begin(), drive.poses().end(), [&](const SE3& a, const SE3& b) {
    auto clearance = [&](const SE3& p) {
      double d = 1e9;
      for (const PedestrianCrossing& c : map.pedestrianCrossings) d = std::min(d, (crossingCentre(c) - p.translation().head<2>()).norm());
      return std::min(d, (removed - p.translation().head<2>()).norm());
    };
    return clearance(a) < clearance(b);
  });
  const Eigen::Vector3d at = far.translation(), ahead = far.linear().col(0), left = far.linear().col(1);
  PedestrianCrossing drawn;
  drawn.id = 900000;
  drawn.edge1 = {at - 1.5 * ahead - 4.0 * left, at - 1.5 * ahead + 4.0 * left};
  drawn.edge2 = {at + 1.5 * ahead - 4.0 * left, at + 1.5 * ahead + 4.0 * left};
  map.pedestrianCrossings.push_back(drawn);
  writeFileAtomically(opened.mapFiles().vectorMap, vectorMapToJson(map));
  return {removed, drawn.id};
}

}  // namespace hdprior::test
