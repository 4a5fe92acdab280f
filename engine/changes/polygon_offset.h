#pragma once
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "engine/changes/change_options.h"

namespace hdprior {

// Where the lidar put the road's edge across one boundary sample at `point`: `offset` metres
// along the sample's outward unit `normal`.
struct EdgeOffset {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();
  double offset = 0.0;
};

// One translation of a drivable area that puts its boundary on the road edges the lidar saw all
// along it: the map holds the polygon shifted (or narrowed on the only side seen). Each sample
// alone stays within the tolerance of a shift of a metre or so; the whole boundary agreeing on
// one translation, and almost nowhere with the map, does not.
struct PolygonOffset {
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();  // city frame, metres; only the observed directions
  int samples = 0;
  double fitShare = 0.0;  // of the samples within ChangeOptions::polygonFitBand of the translation
  double mapShare = 0.0;  // of the samples the translation moves (by the band or more), within the band of the map

  // Whether a sample's edge lies where the translation puts it, away from the map's boundary.
  bool explains(const EdgeOffset& e, const ChangeOptions& o) const;
};

// The polygon's offset if its samples show one (ChangeOptions::polygonMinSamples and the shares),
// else nothing. Nothing too where the other polygons' edges nearby (`around`, within
// ChangeOptions::polygonNeighbourhood) that the translation would move follow it more often than
// they stay on the map: then the poses are off there, not the polygon.
std::optional<PolygonOffset> polygonOffset(const std::vector<EdgeOffset>& samples, const std::vector<EdgeOffset>& around,
                                           const ChangeOptions& options);

}  // namespace hdprior
