#include "engine/lidar/sweep_road_points.h"

#include <Eigen/Geometry>

#include "engine/lidar/sweep_points.h"

namespace hdprior {

std::vector<Eigen::Vector2d> sweepRoadPoints(const LidarSweep& sweep, const Eigen::Matrix3d& egoLevel,
                                             const SweepRoadPointOptions& options) {
  const SubmapSweep one{&sweep, egoLevel, Eigen::Vector3d::Zero()};
  return submapRoadPoints(std::span(&one, 1), options).road;
}

LabelledSubmap labelSubmap(std::span<const SubmapSweep> sweeps, const SweepRoadPointOptions& options) {
  LabelledSubmap out;
  for (const SubmapSweep& s : sweeps) {
    const std::vector<Eigen::Vector3d> points = sweepPoints(*s.sweep);
    const std::vector<uint8_t> ground = segmentGround(points, options.ground);
    const std::vector<uint8_t> road = extractRoadPoints(points, sweepRings(*s.sweep), ground, options.road);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(s.keyframeTSweep.z(), Eigen::Vector3d::UnitZ()).toRotationMatrix() * s.egoLevel;
    const Eigen::Vector3d t(s.keyframeTSweep.x(), s.keyframeTSweep.y(), 0.0);
    for (const Eigen::Vector3d& p : points) out.points.push_back(R * p + t);
    out.ground.insert(out.ground.end(), ground.begin(), ground.end());
    out.road.insert(out.road.end(), road.begin(), road.end());
  }
  return out;
}

PlanarRoadPoints planarRoadPoints(const LabelledSubmap& submap, double thinCell) {
  PlanarRoadPoints out;
  out.road = planarPoints(submap.points, submap.road, thinCell);
  for (size_t i = 0; i < submap.points.size(); ++i) {
    if (submap.road[i] == kCurbPoint) out.curb.emplace_back(submap.points[i].x(), submap.points[i].y());
  }
  return out;
}

PlanarRoadPoints submapRoadPoints(std::span<const SubmapSweep> sweeps, const SweepRoadPointOptions& options) {
  return planarRoadPoints(labelSubmap(sweeps, options), options.thinCell);
}

}  // namespace hdprior
