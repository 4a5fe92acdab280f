#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/map/grid_geometry.h"

namespace hdprior {

// GDAL's affine geotransform: a pixel corner (col, row) lies at city
//   x = c[0] + col * c[1] + row * c[2],   y = c[3] + col * c[4] + row * c[5].
// North-up rasters (what QGIS expects) have c[2] = c[4] = 0 and a negative c[5].
using GeoTransform = std::array<double, 6>;

inline Eigen::Vector2d pixelToCity(const GeoTransform& c, double col, double row) {
  return {c[0] + col * c[1] + row * c[2], c[3] + col * c[4] + row * c[5]};
}

// One band, row-major, row 0 is the first row of the file (the northern-most for north-up).
template <typename T>
struct GeoRaster {
  int rows = 0, cols = 0;
  GeoTransform transform{0, 1, 0, 0, 0, -1};
  std::vector<T> values;
  std::optional<double> noData;
  std::string description;  // band description
};

// The transform of a GridGeometry written north-up: file row 0 = grid row rows-1.
GeoTransform northUpTransform(const GridGeometry& grid);
// Grid values (row 0 = south, GridGeometry order) reordered north-up with that transform.
template <typename T>
GeoRaster<T> northUpRaster(const GridGeometry& grid, const std::vector<T>& values) {
  GeoRaster<T> out;
  out.rows = grid.rows;
  out.cols = grid.cols;
  out.transform = northUpTransform(grid);
  out.values.resize(values.size());
  for (int r = 0; r < grid.rows; ++r) {
    std::copy_n(values.begin() + ptrdiff_t(grid.index(0, r)), grid.cols,
                out.values.begin() + ptrdiff_t(grid.index(0, grid.rows - 1 - r)));
  }
  return out;
}

// Deflate-compressed tiled GeoTIFF, written to a temporary name beside `path` and renamed
// into place. The city frame is recorded as a local (engineering) coordinate system in
// metres. Throws Error naming the file on failure and leaves nothing behind.
void writeGeoTiff(const std::filesystem::path& path, const GeoRaster<uint8_t>& raster);
void writeGeoTiff(const std::filesystem::path& path, const GeoRaster<float>& raster);
// Band 1 of any GDAL-readable raster, converted to float32. Throws Error naming the file.
GeoRaster<float> readGeoTiffFloat(const std::filesystem::path& path);

}  // namespace hdprior
