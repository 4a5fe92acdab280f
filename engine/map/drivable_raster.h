#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "engine/io/vector_map.h"
#include "engine/map/grid_geometry.h"

namespace hdprior {

struct DrivableRasterOptions {
  double resolution = 0.10;      // metres per cell (the paper's 10 cm)
  double margin = 10.0;          // empty border around the polygons' extent, metres (at least one cell)
  size_t maxCells = 300'000'000;  // refuse rasters larger than this (a corrupt or absurd extent)
  // City x, y: raster only this part of the map (a check along one drive of a large map).
  std::optional<Eigen::AlignedBox2d> window;
};

// The union of all drivable-area polygons of a map, rasterised. A cell is drivable when
// its centre lies inside at least one polygon (even-odd rule per polygon, OR over
// polygons). The grid origin is snapped to a multiple of the resolution, so grids built at
// resolutions that divide each other line up. Row 0 is the southern-most row (see
// GridGeometry).
//
// Both representations of the paper are kept: the filled region ("surface points", one per
// drivable cell centre) and the boundary of the union ("curb points", sampled every
// `resolution` metres along the polygon edges that border non-drivable cells).
class DrivableRaster {
 public:
  // A horizontal run of drivable cells [begin, end) in one row.
  struct Run {
    int32_t begin = 0, end = 0;
  };

  // Throws Error(source, ...) for a map without drivable areas, a zero-area polygon,
  // non-finite coordinates, bad options or an extent over options.maxCells.
  static DrivableRaster build(const VectorMap& map, const DrivableRasterOptions& options,
                              const std::string& source);

  const GridGeometry& geometry() const { return geometry_; }
  bool drivable(int col, int row) const {
    return geometry_.inside(col, row) && (bits_[size_t(row) * wordsPerRow_ + size_t(col >> 6)] >> (col & 63)) & 1u;
  }
  bool contains(const Eigen::Vector2d& city) const;  // false outside the grid
  // One byte per cell (1 = drivable), row-major in GridGeometry order.
  std::vector<uint8_t> cellBytes() const;

  std::span<const Run> runs(int row) const {
    return {runs_.data() + rowStart_[size_t(row)], runs_.data() + rowStart_[size_t(row) + 1]};
  }
  size_t drivableCellCount() const { return drivableCells_; }
  double area() const { return double(drivableCells_) * geometry_.resolution * geometry_.resolution; }

  std::vector<Eigen::Vector2d> surfacePoints() const;  // centres of drivable cells, row by row
  const std::vector<Eigen::Vector2d>& boundaryPoints() const { return boundaryPoints_; }

 private:
  std::vector<Eigen::Vector2d> traceBoundary(const VectorMap& map) const;
  void setBits(int row, const Run& run);

  GridGeometry geometry_;
  std::vector<uint64_t> bits_;  // one bit per cell, each row padded to whole words
  size_t wordsPerRow_ = 0;
  std::vector<Run> runs_;
  std::vector<size_t> rowStart_;  // rows + 1 offsets into runs_
  size_t drivableCells_ = 0;
  std::vector<Eigen::Vector2d> boundaryPoints_;
};

}  // namespace hdprior
