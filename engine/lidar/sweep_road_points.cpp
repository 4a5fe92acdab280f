#include "engine/lidar/sweep_road_points.h"

#include "engine/lidar/sweep_points.h"

namespace hdprior {

LabelledSweep labelSweep(const LidarSweep& sweep, const Eigen::Matrix3d& egoLevel, const SweepRoadPointOptions& options) {
  LabelledSweep out;
  const std::vector<Eigen::Vector3d> points = sweepPoints(sweep);
  out.ground = segmentGround(points, options.ground);
  out.road = extractRoadPoints(points, sweepRings(sweep), out.ground, options.road);
  out.points.reserve(points.size());
  for (const Eigen::Vector3d& p : points) out.points.push_back(egoLevel * p);
  return out;
}

PlanarRoadPoints planarRoadPoints(const LabelledSweep& sweep, double thinCell) {
  SweepRoadPointOptions keys;
  keys.thinCell = thinCell;
  checkOptionRanges("road point options", optionFields(keys));
  PlanarRoadPoints out;
  out.road = planarPoints(sweep.points, sweep.road, thinCell);
  for (size_t i = 0; i < sweep.points.size(); ++i) {
    if (sweep.road[i] == kCurbPoint) out.curb.emplace_back(sweep.points[i].x(), sweep.points[i].y());
  }
  return out;
}

PlanarRoadPoints sweepRoadPoints(const LidarSweep& sweep, const Eigen::Matrix3d& egoLevel, const SweepRoadPointOptions& options) {
  return planarRoadPoints(labelSweep(sweep, egoLevel, options), options.thinCell);
}

}  // namespace hdprior
