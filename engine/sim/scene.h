#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/map/boundary_distance.h"
#include "engine/map/grid_geometry.h"
#include "engine/sim/road_paint.h"
#include "engine/sim/roadside.h"

namespace hdprior {

// Ground-truth class of a simulated lidar return (the lidar_labels sidecar).
enum class PointLabel : uint8_t { Road = 0, SidewalkCurb = 1, OtherGround = 2, Object = 3 };

// A vertical prism over an oriented rectangle: facades, cars.
struct SceneBox {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double yaw = 0.0;
  Eigen::Vector2d halfSize = Eigen::Vector2d::Ones();  // along the box's x (yaw) and y axes
  double zMin = 0.0, zMax = 1.0;
  uint8_t reflectivity = 40;
};

// A vertical cylinder: poles, tree trunks and crowns.
struct SceneCylinder {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.1;
  double zMin = 0.0, zMax = 1.0;
  uint8_t reflectivity = 40;
};

// A car driving along a lane route at constant speed from `startS` (metres along the path)
// at time `startNs`; it leaves the world at the path's end.
struct MovingCar {
  std::vector<Eigen::Vector2d> path;  // resampled every metre
  double startS = 0.0, speed = 8.0;
  int64_t startNs = 0;
  double zOffset = 0.25, height = 1.5;
  // The car's box at tNs; nullopt once it has left its path.
  std::optional<SceneBox> boxAt(int64_t tNs, double groundZ) const;
  std::optional<Eigen::Vector2d> centreAt(int64_t tNs) const;
};

// The world the lidar is ray-cast into: a height field (ground height plus a curb step up
// to the sidewalks outside the drivable area) and static prisms and cylinders in a uniform
// 2-D grid, plus moving cars. City frame, metres.
class Scene {
 public:
  // ground: heights on `grid` (row-major, no NaN); curb: signed distance to the drivable
  // area's boundary (negative on the road).
  Scene(GridGeometry groundGrid, std::vector<float> groundHeights, BoundaryDistance curbDistance,
        double sidewalkWidth, uint64_t seed);

  // The physical roadside of a scene family (kerb shapes and gaps, gutters, camber, sloped
  // sidewalks, islands, the kerb displaced from the map); without one, today's kerbs: a
  // vertical step of curbHeight() at the map's boundary, flat road and sidewalks.
  void setRoadside(Roadside roadside);
  const Roadside* roadside() const { return roadside_ ? &*roadside_ : nullptr; }
  // Lane lines and zebra crossings on the road (brighter returns; still labelled road).
  void setPaint(RoadPaint paint) { paint_ = std::move(paint); }
  const RoadPaint& paint() const { return paint_; }

  double groundHeight(const Eigen::Vector2d& city) const;  // bilinear, clamped at the border
  // Signed distance to the physical kerb (the map's drivable boundary unless a roadside moves
  // it or adds islands); +infinity outside its grid.
  double boundaryDistance(const Eigen::Vector2d& city) const;
  // Signed distance to the map's drivable boundary; +infinity outside its grid.
  double mapBoundaryDistance(const Eigen::Vector2d& city) const;
  // Curb height (without a roadside 0.10..0.20 m, varying smoothly along the streets).
  double curbHeight(const Eigen::Vector2d& city) const;
  // The surface at a point: distance to the physical kerb, height above the ground height,
  // and the sidewalk's width there.
  struct SurfacePoint {
    double boundary = 0.0, rise = 0.0, sidewalkWidth = 0.0;
  };
  SurfacePoint surfacePoint(const Eigen::Vector2d& city) const;
  // Ground plus curb where the point is off the road (plus the roadside's profile).
  double surfaceHeight(const Eigen::Vector2d& city) const;
  double sidewalkWidth() const { return sidewalkWidth_; }
  double sidewalkWidthAt(const Eigen::Vector2d& city) const;
  // Bounds of |grad surfaceHeight| used by the ray marcher (away from kerbs and gutters):
  // anywhere, of the ground height alone, and on the road. Without a roadside all the same.
  double maxSlope() const { return maxSlope_; }
  double groundSlope() const { return groundSlope_; }
  double roadSlope() const { return roadSlope_; }
  // Bound of surfaceHeight - groundHeight (0.2 m without a roadside).
  double maxRise() const { return maxRise_; }
  // Of the road, the sidewalks and the ground beyond.
  uint8_t reflectivity(PointLabel label) const;
  // The road's at a point: with the roadside's bright asphalt patches and flecks.
  uint8_t roadReflectivityAt(const Eigen::Vector2d& city) const;
  const GridGeometry& groundGrid() const { return groundGrid_; }

  void addBox(const SceneBox& box) { boxes_.push_back(box); }
  void addCylinder(const SceneCylinder& c) { cylinders_.push_back(c); }
  void addMovingCar(MovingCar car) { movingCars_.push_back(std::move(car)); }
  const std::vector<SceneBox>& boxes() const { return boxes_; }
  // cos and sin of each box's yaw (filled by index()).
  const std::vector<Eigen::Vector2d>& boxAxes() const { return boxAxes_; }
  const std::vector<SceneCylinder>& cylinders() const { return cylinders_; }
  const std::vector<MovingCar>& movingCars() const { return movingCars_; }
  // The moving cars at tNs within `radius` of `egoXY`, leaving out any closer than
  // `clearance` (a car never drives through the ego vehicle).
  std::vector<SceneBox> movingBoxesAt(int64_t tNs, const Eigen::Vector2d& egoXY, double radius,
                                      double clearance) const;

  // Builds the 2-D object grid; call after the last addBox/addCylinder.
  void index(double cellSize = 4.0);
  const GridGeometry& objectGrid() const { return objectGrid_; }
  // Items of an object cell: index into boxes(), or cylinders() + kCylinderBit.
  static constexpr uint32_t kCylinderBit = 0x80000000u;
  std::span<const uint32_t> cellItems(int col, int row) const {
    const size_t i = objectGrid_.index(col, row);
    return {items_.data() + cellStart_[i], items_.data() + cellStart_[i + 1]};
  }

 private:
  GridGeometry groundGrid_;
  std::vector<float> heights_;
  BoundaryDistance curb_;
  double sidewalkWidth_;
  double maxSlope_ = 0.1, groundSlope_ = 0.1, roadSlope_ = 0.1, maxRise_ = 0.2;
  std::optional<Roadside> roadside_;
  RoadPaint paint_;
  double curbPhase_[2] = {0.0, 0.0};
  uint64_t textureSalt_ = 0;
  std::vector<SceneBox> boxes_;
  std::vector<Eigen::Vector2d> boxAxes_;
  std::vector<SceneCylinder> cylinders_;
  std::vector<MovingCar> movingCars_;
  GridGeometry objectGrid_;
  std::vector<uint32_t> cellStart_, items_;
};

}  // namespace hdprior
