#include "engine/map/ground_height.h"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "engine/error.h"
#include "engine/map/geotiff.h"

namespace hdprior {
namespace fs = std::filesystem;

GroundHeight::GroundHeight(const Sim2& imgSim2City, int rows, int cols, std::vector<float> heights, std::string source)
    : imgSim2City_(imgSim2City), rows_(rows), cols_(cols), heights_(std::move(heights)), source_(std::move(source)) {
  if (rows <= 0 || cols <= 0) throw Error(source_, "ground-height raster is empty");
  if (heights_.size() != size_t(rows) * size_t(cols)) {
    throw Error(source_, "ground-height raster holds " + std::to_string(heights_.size()) + " values, expected " +
                             std::to_string(rows) + " x " + std::to_string(cols));
  }
  if (!(imgSim2City.s > 0.0) || !std::isfinite(imgSim2City.s) || !imgSim2City.R.allFinite() ||
      !imgSim2City.t.allFinite()) {
    throw Error(source_, "ground-height Sim2 is not a finite similarity transform");
  }
}

GroundHeight GroundHeight::fromNpy(const NpyArray& array, const Sim2& imgSim2City, const std::string& source) {
  if (array.shape.size() != 2) throw Error(source, "ground-height raster is not 2-D");
  if (array.shape[0] > size_t(1) << 30 || array.shape[1] > size_t(1) << 30) {
    throw Error(source, "ground-height raster is implausibly large");
  }
  return GroundHeight(imgSim2City, int(array.shape[0]), int(array.shape[1]), array.values, source);
}

double GroundHeight::heightAt(const Eigen::Vector2d& city) const {
  const Eigen::Vector2d uv = imgSim2City_.cityToImage(city);
  if (!(uv.x() >= 0.0 && uv.y() >= 0.0 && uv.x() < cols_ && uv.y() < rows_)) return NAN;
  return pixel(int(uv.x()), int(uv.y()));
}

double GroundHeight::bilinearAt(const Eigen::Vector2d& city) const { return interpolate(city, nullptr); }

Eigen::Vector2d GroundHeight::gradientAt(const Eigen::Vector2d& city) const {
  Eigen::Vector2d g;
  if (std::isnan(interpolate(city, &g))) return Eigen::Vector2d::Constant(NAN);
  return g;
}

// h = sum(w_i h_i) / sum(w_i) over the valid corners; the gradient follows the quotient rule
// in image coordinates and is carried to the city frame by d(u, v)/dp = s R.
double GroundHeight::interpolate(const Eigen::Vector2d& city, Eigen::Vector2d* gradient) const {
  if (std::isnan(heightAt(city))) return NAN;
  const Eigen::Vector2d uv = imgSim2City_.cityToImage(city) - Eigen::Vector2d(0.5, 0.5);
  const int c0 = int(std::floor(uv.x())), r0 = int(std::floor(uv.y()));
  const double fu = uv.x() - c0, fv = uv.y() - r0;
  double N = 0, D = 0, Nu = 0, Nv = 0, Du = 0, Dv = 0;
  for (int dr = 0; dr <= 1; ++dr) {
    for (int dc = 0; dc <= 1; ++dc) {
      const int c = c0 + dc, r = r0 + dr;
      if (c < 0 || r < 0 || c >= cols_ || r >= rows_) continue;
      const double h = pixel(c, r);
      if (std::isnan(h)) continue;
      const double wu = dc ? fu : 1.0 - fu, wv = dr ? fv : 1.0 - fv;
      const double dwu = dc ? 1.0 : -1.0, dwv = dr ? 1.0 : -1.0;  // d(wu)/du, d(wv)/dv
      N += wu * wv * h;
      D += wu * wv;
      Nu += dwu * wv * h;
      Nv += wu * dwv * h;
      Du += dwu * wv;
      Dv += wu * dwv;
    }
  }
  if (gradient) {
    const Eigen::Vector2d dUv((Nu * D - N * Du) / (D * D), (Nv * D - N * Dv) / (D * D));
    *gradient = imgSim2City_.s * imgSim2City_.R.transpose() * dUv;
  }
  return N / D;
}

RollPitch rollPitchFromGradient(const Eigen::Vector2d& g, double yaw) {
  const Eigen::Vector2d forward(std::cos(yaw), std::sin(yaw)), left(-std::sin(yaw), std::cos(yaw));
  return {std::asin(g.dot(left) / std::sqrt(1.0 + g.squaredNorm())), -std::atan(g.dot(forward))};
}

Eigen::Vector2d GroundHeight::slopeAt(const Eigen::Vector2d& city, double radius) const {
  const Eigen::Vector2d nan = Eigen::Vector2d::Constant(NAN);
  if (std::isnan(heightAt(city)) || !(radius > 0.0)) return nan;
  const Eigen::Vector2d uv = imgSim2City_.cityToImage(city);
  const double reach = radius * imgSim2City_.s + 1.0;
  const int c0 = std::max(0, int(std::floor(uv.x() - reach))), c1 = std::min(cols_ - 1, int(std::ceil(uv.x() + reach)));
  const int r0 = std::max(0, int(std::floor(uv.y() - reach))), r1 = std::min(rows_ - 1, int(std::ceil(uv.y() + reach)));
  // Normal equations of z = a + b dx + c dy in coordinates relative to `city`.
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  int used = 0;
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      const double h = pixel(c, r);
      if (std::isnan(h)) continue;
      const Eigen::Vector2d d = imgSim2City_.imageToCity(Eigen::Vector2d(c + 0.5, r + 0.5)) - city;
      if (d.squaredNorm() > radius * radius) continue;
      const Eigen::Vector3d x(1.0, d.x(), d.y());
      A += x * x.transpose();
      rhs += x * h;
      ++used;
    }
  }
  if (used < 6) return nan;
  const Eigen::Vector3d plane = A.ldlt().solve(rhs);
  return plane.allFinite() ? Eigen::Vector2d(plane(1), plane(2)) : nan;
}

RollPitch GroundHeight::rollPitchAt(const Eigen::Vector2d& city, double yaw, double radius) const {
  const Eigen::Vector2d g = slopeAt(city, radius);
  if (!g.allFinite()) return {NAN, NAN};
  return rollPitchFromGradient(g, yaw);
}

GroundHeight readGroundHeight(const fs::path& npy, const fs::path& sim2) {
  return GroundHeight::fromNpy(readNpy(npy), readSim2(sim2), npy.string());
}

namespace {

// A 2x2 matrix that is s^-1 times a rotation, s > 0: returns s, or 0 if it is not one.
double similarityScale(const Eigen::Matrix2d& A) {
  const double det = A.determinant();
  if (!(det > 0.0)) return 0.0;
  const Eigen::Matrix2d rotation = A / std::sqrt(det);
  if (!(rotation.transpose() * rotation).isIdentity(1e-9)) return 0.0;
  return 1.0 / std::sqrt(det);
}

}  // namespace

GroundHeight readGroundHeightGeoTiff(const fs::path& tif) {
  GeoRaster<float> raster = readGeoTiffFloat(tif);
  const GeoTransform& c = raster.transform;
  // City offset per pixel step along (col, row) as stored, and with the rows flipped.
  Eigen::Matrix2d A;
  A << c[1], c[2], c[4], c[5];
  const Eigen::Matrix2d flipped = A * Eigen::Vector2d(1.0, -1.0).asDiagonal();
  const bool northUp = similarityScale(flipped) > 0.0;
  const Eigen::Matrix2d image = northUp ? flipped : A;  // city delta per image (u, v) step
  const double s = similarityScale(image);
  if (!(s > 0.0) || !std::isfinite(s)) {
    throw Error(tif.string(), "geotransform is not a north-up or south-up similarity with square pixels");
  }
  // Image (0, 0) is the corner of file row 0 (south-up) or of file row rows (north-up).
  const Eigen::Vector2d imageOrigin = pixelToCity(c, 0.0, northUp ? double(raster.rows) : 0.0);
  Sim2 sim2;
  sim2.s = s;
  sim2.R = (image * s).transpose();  // image = R^T / s
  sim2.t = -sim2.R * imageOrigin;
  std::vector<float> heights(raster.values.size());
  for (int r = 0; r < raster.rows; ++r) {
    const int fileRow = northUp ? raster.rows - 1 - r : r;
    for (int col = 0; col < raster.cols; ++col) {
      float h = raster.values[size_t(fileRow) * size_t(raster.cols) + size_t(col)];
      if (raster.noData && !std::isnan(*raster.noData) && h == float(*raster.noData)) h = NAN;
      heights[size_t(r) * size_t(raster.cols) + size_t(col)] = h;
    }
  }
  return GroundHeight(sim2, raster.rows, raster.cols, std::move(heights), tif.string());
}

void writeGroundHeightGeoTiff(const fs::path& tif, const GroundHeight& height) {
  const Sim2& sim2 = height.imgSim2City();
  // Image corner (u, v) is at city R^T ((u, v) / s - t); file row j is image row rows - 1 - j.
  const Eigen::Matrix2d image = sim2.R.transpose() / sim2.s;
  const Eigen::Vector2d corner = sim2.imageToCity(Eigen::Vector2d(0.0, double(height.rows())));
  GeoRaster<float> raster;
  raster.rows = height.rows();
  raster.cols = height.cols();
  raster.transform = {corner.x(), image(0, 0), -image(0, 1), corner.y(), image(1, 0), -image(1, 1)};
  raster.noData = NAN;
  raster.description = "ground height (m, city frame)";
  raster.values.resize(height.heights().size());
  for (int r = 0; r < height.rows(); ++r) {
    std::copy_n(height.heights().begin() + ptrdiff_t(size_t(r) * size_t(height.cols())), height.cols(),
                raster.values.begin() + ptrdiff_t(size_t(height.rows() - 1 - r) * size_t(height.cols())));
  }
  writeGeoTiff(tif, raster);
}

}  // namespace hdprior
