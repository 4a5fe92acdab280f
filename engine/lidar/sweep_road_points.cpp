#include "engine/lidar/sweep_road_points.h"

#include "engine/lidar/sweep_points.h"

namespace hdprior {

std::vector<Eigen::Vector2d> sweepRoadPoints(const LidarSweep& sweep, const Eigen::Matrix3d& egoLevel,
                                             const SweepRoadPointOptions& options) {
  std::vector<Eigen::Vector3d> points = sweepPoints(sweep);
  const std::vector<uint8_t> ground = segmentGround(points, options.ground);
  const std::vector<uint8_t> road = extractRoadPoints(points, sweepRings(sweep), ground, options.road);
  for (Eigen::Vector3d& p : points) p = egoLevel * p;
  return planarPoints(points, road, options.thinCell);
}

}  // namespace hdprior
