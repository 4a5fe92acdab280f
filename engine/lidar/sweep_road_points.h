#pragma once
#include <span>
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

// One sweep of a key-frame sub-map: its levelling rotation and its SE(2) pose (x, y, yaw) in the
// level frame of the key frame.
struct SubmapSweep {
  const LidarSweep* sweep = nullptr;
  Eigen::Matrix3d egoLevel = Eigen::Matrix3d::Identity();
  Eigen::Vector3d keyframeTSweep = Eigen::Vector3d::Zero();
};

struct PlanarRoadPoints {
  std::vector<Eigen::Vector2d> road;  // thinned
  std::vector<Eigen::Vector2d> curb;  // the road points at curbs (kCurbPoint), all of them
};

// The points of several sweeps in the key frame's level frame with their ground flags (segmentGround)
// and road flags (0, kRoadPoint or kCurbPoint: extractRoadPoints), each computed per sweep.
struct LabelledSubmap {
  std::vector<Eigen::Vector3d> points;
  std::vector<uint8_t> ground, road;
};
LabelledSubmap labelSubmap(std::span<const SubmapSweep> sweeps, const SweepRoadPointOptions& options = {});

// The road points of a labelled sub-map on the plane (thinned) and its curb points.
PlanarRoadPoints planarRoadPoints(const LabelledSubmap& submap, double thinCell);

// The road points of several sweeps in the key frame's level frame, thinned together.
PlanarRoadPoints submapRoadPoints(std::span<const SubmapSweep> sweeps, const SweepRoadPointOptions& options = {});

}  // namespace hdprior
