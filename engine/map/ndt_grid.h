#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/map/grid_geometry.h"

namespace hdprior {

class DrivableRaster;

struct NdtGridOptions {
  double cellSize = 1.0;        // metres; a whole multiple of the raster resolution
  int minPoints = 5;            // drivable raster cells needed for a valid NDT cell
  double minEigenRatio = 0.01;  // smallest / largest covariance eigenvalue after regularisation
};

// The normal distribution of the drivable surface inside one NDT cell. The covariance is the
// second moment of the drivable raster cells taken as squares (the point covariance of their
// centres plus resolution^2 / 12 on the diagonal), with near-singular eigenvalues lifted to
// minEigenRatio times the largest one.
struct NdtCell {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();           // city frame
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Identity();
  Eigen::Matrix2d information = Eigen::Matrix2d::Identity();  // inverse covariance
  int count = 0;                                              // drivable raster cells; 0 = not valid
  bool valid() const { return count > 0; }
};

// The NDT grid of the drivable area ("map" side of the scan-to-map matching): a dense array
// of cells over the raster's extent, so lookup is O(1). Its origin is a multiple of
// cellSize in city coordinates; rows grow northwards as in GridGeometry.
class NdtGrid {
 public:
  // Throws Error if cellSize is not a whole multiple of the raster resolution or an NDT
  // cell cannot hold minPoints raster cells.
  static NdtGrid build(const DrivableRaster& raster, const NdtGridOptions& options = {});

  const GridGeometry& geometry() const { return geometry_; }
  double cellSize() const { return geometry_.resolution; }
  // Index into cells() of grid cell (col, row), -1 where there is no valid distribution.
  const std::vector<int32_t>& cellIndex() const { return index_; }
  // The valid cell at (col, row) or holding a city point, or nullptr.
  const NdtCell* at(int col, int row) const;
  const NdtCell* cellAt(const Eigen::Vector2d& city) const;
  const std::vector<NdtCell>& cells() const { return cells_; }  // valid cells, row by row
  size_t validCellCount() const { return cells_.size(); }

 private:
  GridGeometry geometry_;
  std::vector<int32_t> index_;  // dense, one per grid cell
  std::vector<NdtCell> cells_;
};

}  // namespace hdprior
