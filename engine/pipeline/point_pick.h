#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/geom/se3.h"
#include "engine/io/lidar_sweep.h"
#include "engine/map/ndt_grid.h"
#include "engine/pipeline/keyframe_inspection.h"

namespace hdprior {

class HdMap;

// The sweep point the user pointed at, as the road points see it.
struct PickedPoint {
  size_t index = 0;  // in the sweep file
  SubmapLabel label = SubmapLabel::Other;
  Eigen::Vector3d city = Eigen::Vector3d::Zero();
  double range = 0.0;              // metres from the sensor origin (ego frame)
  double heightAboveGround = 0.0;  // metres above the ground-height raster; NaN outside it
  double distance = 0.0;           // metres in the plane from the picked place
  int intensity = 0, laserNumber = 0;
};

// What lies at a city point: the nearest sweep point within the radius, the drivable-area
// polygon holding the place, and the NDT cell there (of the grid asked for).
struct Pick {
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  std::optional<PickedPoint> point;
  std::optional<int64_t> drivableArea;
  std::optional<NdtCell> cell;
  double cellSize = 0.0;
};

struct PickOptions {
  double radius = 0.5;                // metres in the plane
  std::optional<double> ndtCellSize;  // the NDT cell too, from the grid of this cell size
};

// `labels` has one label per sweep point (sweepPointLabels); cityTEgo places the sweep.
Pick pickAt(const Eigen::Vector2d& at, const LidarSweep& sweep, const std::vector<SubmapLabel>& labels, const SE3& cityTEgo,
            const HdMap& map, const PickOptions& options = {});

// "pick: road point 12.31 m away ..."; one line, no newline.
std::string pickText(const Pick& pick);

}  // namespace hdprior
