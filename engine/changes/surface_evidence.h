#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/geom/se3.h"
#include "engine/lidar/sweep_road_points.h"
#include "engine/map/grid_geometry.h"

namespace hdprior {

class GroundHeight;

// What the lidar saw of the ground in one cell of the city plane, summed over the log's frames.
struct SurfaceCell {
  uint16_t road = 0;     // road points: the road walk reached them
  uint16_t offRoad = 0;  // ground points it did not reach (sidewalks, verges, or road it could not see into)
  uint16_t curb = 0;     // road points where the walk ended at a height step (kerbs)
  float groundOffsetSum = 0;  // of the ground points: height minus the ground-height raster, summed
  uint16_t groundOffsetCount = 0;
  int32_t firstFrame = -1;  // the first frame that saw the cell
  int32_t bestFrame = -1;   // the frame that saw it from closest
  float bestRange = 1e9f;   // metres from that frame's ego origin

  bool observed() const { return road + offRoad > 0; }
};

// A cell's surface as the change check reads it (classifySurface).
enum class Surface : uint8_t {
  Unknown,  // seen too little
  Road,     // the road walk reached most of its ground points
  NotRoad,  // ground the walk saw and did not reach (beyond a kerb or a gutter, or where it did not go)
};

// The lidar's ground evidence in city-frame cells over an area: every labelled sweep (ground
// segmentation and road walk) added at its pose, the poses the run made globally consistent.
class SurfaceEvidence {
 public:
  SurfaceEvidence() = default;
  explicit SurfaceEvidence(const GridGeometry& geometry) : geometry_(geometry), cells_(geometry.cellCount()) {}
  // A grid of `cell` metres covering the positions with `margin` metres around them.
  static SurfaceEvidence around(const std::vector<Eigen::Vector2d>& positions, double margin, double cell);

  // The labelled sweep of `frame` at city_T_ego (its points are levelled: labelSweep with the
  // pose's roll and pitch). `ground` gives each ground point's offset to the raster (may be null).
  void add(int frame, const LabelledSweep& sweep, const SE3& cityTEgo, const GroundHeight* ground);

  const GridGeometry& geometry() const { return geometry_; }
  const std::vector<SurfaceCell>& cells() const { return cells_; }
  const SurfaceCell* cellAt(const Eigen::Vector2d& city) const {
    int c, r;
    return geometry_.cellOf(city, c, r) ? &cells_[geometry_.index(c, r)] : nullptr;
  }
  const SurfaceCell& cell(int col, int row) const { return cells_[geometry_.index(col, row)]; }
  // Per cell, once classifySurface has run; Unknown before.
  Surface surface(size_t index) const { return surfaces_.empty() ? Surface::Unknown : surfaces_[index]; }
  Surface surfaceAt(const Eigen::Vector2d& city) const {
    int c, r;
    return geometry_.cellOf(city, c, r) ? surface(geometry_.index(c, r)) : Surface::Unknown;
  }
  void setSurfaces(std::vector<Surface> surfaces) { surfaces_ = std::move(surfaces); }

 private:
  GridGeometry geometry_;
  std::vector<SurfaceCell> cells_;
  std::vector<Surface> surfaces_;
};

}  // namespace hdprior
