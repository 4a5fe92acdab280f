#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

namespace hdprior {

// A regular axis-aligned grid on the city plane. Cell (col, row) covers
//   x in [origin.x + col * resolution, origin.x + (col + 1) * resolution)
//   y in [origin.y + row * resolution, origin.y + (row + 1) * resolution)
// so row 0 is the southern-most row and rows grow northwards (+y). Cells are stored
// row-major: index = row * cols + col. (GeoTIFF export flips the rows to north-up.)
struct GridGeometry {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // city x, y of the corner of cell (0, 0)
  double resolution = 1.0;                           // metres per cell
  int cols = 0, rows = 0;

  size_t cellCount() const { return size_t(cols) * size_t(rows); }
  size_t index(int col, int row) const { return size_t(row) * size_t(cols) + size_t(col); }
  bool inside(int col, int row) const { return col >= 0 && row >= 0 && col < cols && row < rows; }

  // Continuous cell coordinates: cell (c, r) spans [c, c+1) x [r, r+1).
  Eigen::Vector2d toCell(const Eigen::Vector2d& city) const { return (city - origin) / resolution; }
  // The cell holding a city point (floor semantics); false outside the grid or for NaN.
  bool cellOf(const Eigen::Vector2d& city, int& col, int& row) const {
    const double u = (city.x() - origin.x()) / resolution, v = (city.y() - origin.y()) / resolution;
    if (!(u >= 0.0 && v >= 0.0 && u < cols && v < rows)) return false;
    col = int(u);
    row = int(v);
    return true;
  }
  Eigen::Vector2d cellCentre(int col, int row) const {
    return origin + resolution * Eigen::Vector2d(col + 0.5, row + 0.5);
  }
  double width() const { return cols * resolution; }
  double height() const { return rows * resolution; }
};

}  // namespace hdprior
