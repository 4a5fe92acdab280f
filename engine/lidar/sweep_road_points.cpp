#include "engine/lidar/sweep_road_points.h"

#include <Eigen/Geometry>

#include "engine/lidar/sweep_points.h"

namespace hdprior {

std::vector<Eigen::Vector2d> sweepRoadPoints(const LidarSweep& sweep, const Eigen::Matrix3d& egoLevel,
                                             const SweepRoadPointOptions& options) {
  const SubmapSweep one{&sweep, egoLevel, Eigen::Vector3d::Zero()};
  return submapRoadPoints(std::span(&one, 1), options).road;
}

PlanarRoadPoints submapRoadPoints(std::span<const SubmapSweep> sweeps, const SweepRoadPointOptions& options) {
  std::vector<Eigen::Vector3d> all;
  std::vector<uint8_t> allRoad;
  for (const SubmapSweep& s : sweeps) {
    std::vector<Eigen::Vector3d> points = sweepPoints(*s.sweep);
    const std::vector<uint8_t> ground = segmentGround(points, options.ground);
    const std::vector<uint8_t> road = extractRoadPoints(points, sweepRings(*s.sweep), ground, options.road);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(s.keyframeTSweep.z(), Eigen::Vector3d::UnitZ()).toRotationMatrix() * s.egoLevel;
    const Eigen::Vector3d t(s.keyframeTSweep.x(), s.keyframeTSweep.y(), 0.0);
    for (const Eigen::Vector3d& p : points) all.push_back(R * p + t);
    allRoad.insert(allRoad.end(), road.begin(), road.end());
  }
  PlanarRoadPoints out;
  out.road = planarPoints(all, allRoad, options.thinCell);
  for (size_t i = 0; i < all.size(); ++i) {
    if (allRoad[i] == kCurbPoint) out.curb.emplace_back(all[i].x(), all[i].y());
  }
  return out;
}

}  // namespace hdprior
