#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "engine/geom/se3.h"
#include "engine/lidar/sweep_road_points.h"

namespace hdprior {
class ArgoverseLog;
class HdMap;
struct LidarSweep;
}  // namespace hdprior

namespace hdprior::render {

// What the layers draw from and does not change between frames. Everything is drawn in
// the city frame shifted by `origin` (a point of the log), so float vertices keep
// millimetres.
struct Scene {
  const ArgoverseLog* log = nullptr;
  const HdMap* map = nullptr;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  // How the sweeps' ground and road points are labelled (the configuration's road_points).
  SweepRoadPointOptions roadPoints;
  // Reference ground labels of one frame's sweep, one byte per point (the ground_labels layer).
  std::vector<uint8_t> groundLabels;
  size_t groundLabelsFrame = 0;

  Eigen::Vector3f local(const Eigen::Vector3d& city) const { return (city - origin).cast<float>(); }
  // The map's ground height at a city (x, y), or `fallback` where it has none.
  double groundZ(const Eigen::Vector2d& xy, double fallback) const;
};

// The current frame: its sweep and ground-truth pose.
struct Frame {
  size_t index = 0;
  int64_t timestampNs = 0;
  SE3 cityTEgo = SE3::Identity();
  std::shared_ptr<const LidarSweep> sweep;
  double groundZ = 0.0;  // city height of the ground under the ego (its z where the map has none)
};

// The scene of a log and its map; origin at the first pose.
Scene makeScene(const ArgoverseLog& log, const HdMap& map);
// Loads frame `index` (its sweep, pose and ground height); throws Error when out of range.
Frame makeFrame(const Scene& scene, size_t index);

}  // namespace hdprior::render
