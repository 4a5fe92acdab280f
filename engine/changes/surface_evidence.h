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
  // The ground points seen from close enough (SurfaceEvidence::surfaceRange) to describe the surface:
  uint16_t near = 0;
  float heightSum = 0;     // city z, metres
  float intensitySum = 0;
  float groundOffsetSum = 0;  // of the ground points: height minus the ground-height raster, summed
  uint16_t groundOffsetCount = 0;
  int32_t firstFrame = -1;  // the first frame that saw the cell
  int32_t bestFrame = -1;   // the frame that saw it from closest
  float bestRange = 1e9f;   // metres from that frame's ego origin

  bool observed() const { return road + offRoad > 0; }
  float height() const { return heightSum / float(near); }  // with near > 0
  float intensity() const { return intensitySum / float(near); }
};

// A cell's surface as the change check reads it (classifySurface).
enum class Surface : uint8_t {
  Unknown,  // not seen, or seen only as a surface the road walk never touched nor bordered
  Road,     // a smooth surface (height and brightness) the road walk reached
  NotRoad,  // a surface beside the road across a height step or a change of brightness (sidewalk, verge, island)
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
  // `raw` is the sweep it was labelled from (its intensities).
  void add(int frame, const LidarSweep& raw, const LabelledSweep& sweep, const SE3& cityTEgo, const GroundHeight* ground);

  // Ground points farther than this from the sensor describe the surface too coarsely (few rings,
  // grazing incidence) and are counted, not measured.
  static constexpr double surfaceRange = 25.0;

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
