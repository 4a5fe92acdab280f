#pragma once
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "engine/map/grid_geometry.h"

namespace hdprior {

class DrivableRaster;

// Signed distance from each raster cell centre to the boundary of the drivable area, metres:
// negative inside, positive outside. Exact Euclidean distance transform (Felzenszwalb &
// Huttenlocher 2012) to the nearest cell of the other kind, minus half a cell so the zero
// level lies on the cell edges between drivable and non-drivable cells. Same grid and row
// order as the raster.
class BoundaryDistance {
 public:
  static BoundaryDistance build(const DrivableRaster& raster);

  const GridGeometry& geometry() const { return geometry_; }
  const std::vector<float>& values() const { return values_; }
  float at(int col, int row) const { return values_[geometry_.index(col, row)]; }
  // Bilinear between cell centres (clamped at the border); NaN outside the grid.
  double distance(const Eigen::Vector2d& city) const;
  // The value of the cell containing the point (a third of the cost, to a cell's accuracy); NaN outside.
  double cellDistance(const Eigen::Vector2d& city) const {
    int col, row;
    return geometry_.cellOf(city, col, row) ? double(at(col, row)) : NAN;
  }

 private:
  GridGeometry geometry_;
  std::vector<float> values_;
};

}  // namespace hdprior
