#pragma once
#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/io/lidar_sweep.h"
#include "engine/lidar/ground_segmentation.h"
#include "engine/lidar/road_points.h"
#include "engine/option_fields.h"

namespace hdprior {

struct SweepRoadPointOptions {
  GroundSegmentationOptions ground;
  RoadPointOptions road;
  double thinCell = 0.10;  // one planar point per this many metres square (0: all)
};
std::vector<OptionField> optionFields(SweepRoadPointOptions& o);  // its own keys (thin_cell), not ground's or road's


// A sweep's points rotated by egoLevel (the vehicle's roll and pitch, so the road plane is level),
// with their ground flags (segmentGround) and road flags (0, kRoadPoint or kCurbPoint:
// extractRoadPoints). In the ego frame's heading.
struct LabelledSweep {
  std::vector<Eigen::Vector3d> points;
  std::vector<uint8_t> ground, road;
};
LabelledSweep labelSweep(const LidarSweep& sweep, const Eigen::Matrix3d& egoLevel, const SweepRoadPointOptions& options = {});

struct PlanarRoadPoints {
  std::vector<Eigen::Vector2d> road;  // thinned
  std::vector<Eigen::Vector2d> curb;  // the road points at curbs (kCurbPoint), all of them
};

// The road points of a labelled sweep projected to (x, y) and thinned, and its curb points.
PlanarRoadPoints planarRoadPoints(const LabelledSweep& sweep, double thinCell);

// A sweep's road and curb points on the map plane: labelSweep, then planarRoadPoints.
PlanarRoadPoints sweepRoadPoints(const LidarSweep& sweep, const Eigen::Matrix3d& egoLevel,
                                 const SweepRoadPointOptions& options = {});

}  // namespace hdprior
