#pragma once
#include <vector>

#include <Eigen/Core>

#include "engine/io/lidar_sweep.h"
#include "engine/lidar/ground_segmentation.h"
#include "engine/lidar/road_points.h"

namespace hdprior {

struct SweepRoadPointOptions {
  GroundSegmentationOptions ground;
  RoadPointOptions road;
  double thinCell = 0.10;  // one planar point per this many metres square (0: all)
};

// A sweep's road points on the map plane: ground segmentation, road extraction, then the
// road points rotated by egoLevel (the vehicle's roll and pitch, so the plane is level)
// and projected to (x, y), thinned. In the ego frame's heading.
std::vector<Eigen::Vector2d> sweepRoadPoints(const LidarSweep& sweep, const Eigen::Matrix3d& egoLevel,
                                             const SweepRoadPointOptions& options = {});

}  // namespace hdprior
