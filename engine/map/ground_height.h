#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/io/npy.h"
#include "engine/io/sim2.h"

namespace hdprior {

// Roll and pitch (radians) of a vehicle standing on the ground surface, for the rotation
// R = Rz(yaw) Ry(pitch) Rx(roll) whose z axis is the surface normal.
struct RollPitch {
  double roll = 0.0, pitch = 0.0;
};

// The ground surface height map g_SHM of the paper: a raster of city-frame heights (metres),
// NaN outside the region of interest. Image convention of Argoverse 2: a city point p has
// image coordinates (u, v) = s * (R p + t) (img_Sim2_city); it lies in column floor(u), row
// floor(v); heights are row-major in that row order. Pixel centres are at (col + 0.5,
// row + 0.5).
class GroundHeight {
 public:
  GroundHeight() = default;
  // Throws Error(source, ...) if heights.size() != rows * cols or a size is zero.
  GroundHeight(const Sim2& imgSim2City, int rows, int cols, std::vector<float> heights, std::string source);
  static GroundHeight fromNpy(const NpyArray& array, const Sim2& imgSim2City, const std::string& source);

  const Sim2& imgSim2City() const { return imgSim2City_; }
  int rows() const { return rows_; }
  int cols() const { return cols_; }
  const std::vector<float>& heights() const { return heights_; }
  const std::string& source() const { return source_; }
  float pixel(int col, int row) const { return heights_[size_t(row) * size_t(cols_) + size_t(col)]; }

  // Argoverse's own query: the value of the pixel holding p; NaN outside the raster.
  double heightAt(const Eigen::Vector2d& city) const;
  // Bilinear between the four surrounding pixel centres, renormalised over the ones that
  // are not NaN. NaN exactly where heightAt is NaN, so both agree on the region of interest.
  double bilinearAt(const Eigen::Vector2d& city) const;
  // Gradient (dz/dx, dz/dy) of bilinearAt in the city frame; NaN where it is NaN. Local:
  // float16 heights are quantised to 1/32..1/16 m, so over 0.3 m pixels it is noisy.
  Eigen::Vector2d gradientAt(const Eigen::Vector2d& city) const;
  // Slope (dz/dx, dz/dy) of the least-squares plane through the valid pixel centres within
  // `radius` metres: the surface under a vehicle's footprint. NaN if fewer than 6 pixels.
  Eigen::Vector2d slopeAt(const Eigen::Vector2d& city, double radius) const;
  // Roll and pitch of a vehicle at `city` heading `yaw`, from slopeAt over `radius`; NaN
  // outside the region of interest.
  RollPitch rollPitchAt(const Eigen::Vector2d& city, double yaw, double radius = 2.0) const;

 private:
  double interpolate(const Eigen::Vector2d& city, Eigen::Vector2d* gradient) const;

  Sim2 imgSim2City_;
  int rows_ = 0, cols_ = 0;
  std::vector<float> heights_;
  std::string source_;
};

RollPitch rollPitchFromGradient(const Eigen::Vector2d& gradient, double yaw);

// The log's *_ground_height_surface____<CITY>.npy with its *___img_Sim2_city.json.
GroundHeight readGroundHeight(const std::filesystem::path& npy, const std::filesystem::path& sim2);
// A single-band GeoTIFF whose geotransform maps pixels to city metres (north-up or
// south-up, square pixels, optionally rotated); its no-data value becomes NaN.
GroundHeight readGroundHeightGeoTiff(const std::filesystem::path& tif);
// Writes the raster north-up as float32 with NaN no-data (atomically).
void writeGroundHeightGeoTiff(const std::filesystem::path& tif, const GroundHeight& height);

}  // namespace hdprior
