#pragma once
#include <vector>

#include <Eigen/Core>

#include "engine/changes/change_options.h"
#include "engine/io/lidar_sweep.h"
#include "engine/lidar/sweep_road_points.h"

namespace hdprior {

// A run of bright road points along one ring: a painted line crossed by the ring.
struct PaintRun {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  int points = 0;
};

// The road paint a sweep shows near the sensor, in its levelled ego frame (x, y).
struct SweepPaint {
  std::vector<Eigen::Vector2d> road;  // every road point within options.paintRange
  std::vector<float> brightness;      // each one's intensity over its ring's lower quartile (as `road`)
  std::vector<PaintRun> runs;
};

// The road points (ground the road walk reached: sidewalks and verges are often brighter than
// asphalt) within options.paintRange, and the runs among them: options.paintRunPoints or more
// returns of one ring, consecutive in azimuth, each brighter than options.paintContrast times the
// median intensity of the ring's road points (of all of them for a ring with few), and within
// options.paintRunGap of the last.
// `labelled` is labelSweep of `sweep` (same points, same order).
SweepPaint findSweepPaint(const LidarSweep& sweep, const LabelledSweep& labelled, const ChangeOptions& options);

}  // namespace hdprior
