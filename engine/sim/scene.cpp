#include "engine/sim/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "engine/sim/splitmix.h"

namespace hdprior {

Scene::Scene(GridGeometry groundGrid, std::vector<float> groundHeights, BoundaryDistance curbDistance,
             double sidewalkWidth, uint64_t seed)
    : groundGrid_(groundGrid), heights_(std::move(groundHeights)), curb_(std::move(curbDistance)),
      sidewalkWidth_(sidewalkWidth) {
  std::mt19937_64 rng(seed);
  textureSalt_ = splitmix(seed ^ 0xa5f417ULL);
  std::uniform_real_distribution<double> phase(0.0, 6.283185307179586);
  curbPhase_[0] = phase(rng);
  curbPhase_[1] = phase(rng);
  // Steepest pixel-to-pixel slope of the ground, plus the curb's own variation.
  double slope = 0.0;
  const int cols = groundGrid_.cols, rows = groundGrid_.rows;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const float h = heights_[groundGrid_.index(c, r)];
      if (c + 1 < cols) slope = std::max(slope, double(std::abs(heights_[groundGrid_.index(c + 1, r)] - h)));
      if (r + 1 < rows) slope = std::max(slope, double(std::abs(heights_[groundGrid_.index(c, r + 1)] - h)));
    }
  // Capped: float16 steps and fill seams make single pixel pairs look steep; a ray that
  // overshoots such a spot is still caught one step later and refined by bisection.
  maxSlope_ = std::clamp(std::sqrt(2.0) * slope / groundGrid_.resolution + 0.01, 0.02, 0.25);
  groundSlope_ = roadSlope_ = maxSlope_;
}

double Scene::groundHeight(const Eigen::Vector2d& city) const {
  const Eigen::Vector2d u = groundGrid_.toCell(city) - Eigen::Vector2d(0.5, 0.5);
  const double x = std::clamp(u.x(), 0.0, double(groundGrid_.cols - 1));
  const double y = std::clamp(u.y(), 0.0, double(groundGrid_.rows - 1));
  const int c0 = std::min(int(x), groundGrid_.cols - 2 < 0 ? 0 : groundGrid_.cols - 2);
  const int r0 = std::min(int(y), groundGrid_.rows - 2 < 0 ? 0 : groundGrid_.rows - 2);
  const int c1 = std::min(c0 + 1, groundGrid_.cols - 1), r1 = std::min(r0 + 1, groundGrid_.rows - 1);
  const double fx = x - c0, fy = y - r0;
  const float* h = heights_.data();
  const double a = h[groundGrid_.index(c0, r0)], b = h[groundGrid_.index(c1, r0)];
  const double c = h[groundGrid_.index(c0, r1)], d = h[groundGrid_.index(c1, r1)];
  return (1 - fy) * ((1 - fx) * a + fx * b) + fy * ((1 - fx) * c + fx * d);
}

void Scene::setRoadside(Roadside roadside) {
  roadSlope_ = std::min(groundSlope_ + roadside.roadSlope(), 0.4);
  maxSlope_ = std::min(groundSlope_ + roadside.maxSlope(), 0.4);
  maxRise_ = roadside.maxRise();
  roadside_ = std::move(roadside);
}

double Scene::mapBoundaryDistance(const Eigen::Vector2d& city) const {
  const double d = curb_.distance(city);
  return std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
}

double Scene::boundaryDistance(const Eigen::Vector2d& city) const {
  const double d = mapBoundaryDistance(city);
  if (!roadside_ || std::isinf(d)) return d;
  return Roadside::physicalDistance(d, roadside_->at(city));
}

double Scene::curbHeight(const Eigen::Vector2d& city) const {
  if (roadside_) return roadside_->at(city).kerbHeight;
  return 0.15 + 0.05 * std::sin(city.x() / 37.0 + curbPhase_[0]) * std::cos(city.y() / 41.0 + curbPhase_[1]);
}

Scene::SurfacePoint Scene::surfacePoint(const Eigen::Vector2d& city) const {
  const double d = mapBoundaryDistance(city);
  if (!roadside_) return {d, d < 0.0 ? 0.0 : curbHeight(city), sidewalkWidth_};
  const Roadside::Sample s = roadside_->at(city);
  const double boundary = std::isinf(d) ? d : Roadside::physicalDistance(d, s);
  return {boundary, std::isinf(boundary) ? 0.0 : roadside_->rise(boundary, s), double(s.sidewalkWidth)};
}

double Scene::surfaceHeight(const Eigen::Vector2d& city) const {
  const double g = groundHeight(city);
  if (roadside_) return g + surfacePoint(city).rise;
  return boundaryDistance(city) < 0.0 ? g : g + curbHeight(city);
}

double Scene::sidewalkWidthAt(const Eigen::Vector2d& city) const {
  return roadside_ ? double(roadside_->at(city).sidewalkWidth) : sidewalkWidth_;
}

uint8_t Scene::reflectivity(PointLabel label) const {
  const RoadsideOptions standard;
  const RoadsideOptions& o = roadside_ ? roadside_->options() : standard;
  return label == PointLabel::Road ? o.roadReflectivity
         : label == PointLabel::SidewalkCurb ? o.sidewalkReflectivity
                                             : o.terrainReflectivity;
}

uint8_t Scene::roadReflectivityAt(const Eigen::Vector2d& city) const {
  const uint8_t road = reflectivity(PointLabel::Road);
  if (!roadside_) return road;
  const RoadsideOptions& o = roadside_->options();
  const bool patch = o.asphaltPatchShare > 0.0 && cellValue(city.x(), city.y(), 0.25, textureSalt_) < o.asphaltPatchShare;
  const bool fleck = o.asphaltFleckShare > 0.0 && cellValue(city.x(), city.y(), 0.02, ~textureSalt_) < o.asphaltFleckShare;
  if (!patch && !fleck) return road;
  return uint8_t(std::clamp(std::lround(road * o.asphaltPatchGain), 0L, 255L));
}

std::optional<Eigen::Vector2d> MovingCar::centreAt(int64_t tNs) const {
  const double s = startS + speed * double(tNs - startNs) * 1e-9;
  if (path.size() < 2 || s < 0.0 || s >= double(path.size() - 1)) return std::nullopt;
  const size_t i = size_t(s);
  const double f = s - double(i);
  return (1 - f) * path[i] + f * path[i + 1];
}

std::optional<SceneBox> MovingCar::boxAt(int64_t tNs, double groundZ) const {
  const auto c = centreAt(tNs);
  if (!c) return std::nullopt;
  const double s = startS + speed * double(tNs - startNs) * 1e-9;
  const size_t i = std::min(size_t(s), path.size() - 2);
  const Eigen::Vector2d dir = path[i + 1] - path[i];
  SceneBox box;
  box.centre = *c;
  box.yaw = std::atan2(dir.y(), dir.x());
  box.halfSize = {2.3, 0.95};
  box.zMin = groundZ + zOffset;
  box.zMax = groundZ + zOffset + height;
  box.reflectivity = 70;
  return box;
}

std::vector<SceneBox> Scene::movingBoxesAt(int64_t tNs, const Eigen::Vector2d& egoXY, double radius,
                                           double clearance) const {
  std::vector<SceneBox> out;
  for (const MovingCar& car : movingCars_) {
    const auto c = car.centreAt(tNs);
    if (!c) continue;
    const double d = (*c - egoXY).norm();
    if (d > radius || d < clearance) continue;
    if (auto box = car.boxAt(tNs, groundHeight(*c))) out.push_back(*box);
  }
  return out;
}

void Scene::index(double cellSize) {
  boxAxes_.clear();
  for (const SceneBox& b : boxes_) boxAxes_.emplace_back(std::cos(b.yaw), std::sin(b.yaw));
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> extents;  // per item, boxes first
  for (const SceneBox& b : boxes_) {
    const Eigen::Vector2d u(std::cos(b.yaw), std::sin(b.yaw)), v(-u.y(), u.x());
    const Eigen::Vector2d r = (u * b.halfSize.x()).cwiseAbs() + (v * b.halfSize.y()).cwiseAbs();
    extents.emplace_back(b.centre - r, b.centre + r);
  }
  for (const SceneCylinder& c : cylinders_)
    extents.emplace_back(c.centre.array() - c.radius, c.centre.array() + c.radius);
  for (const auto& [a, b] : extents) {
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(b);
  }
  if (extents.empty()) lo = hi = Eigen::Vector2d::Zero();
  objectGrid_.origin = (lo / cellSize).array().floor() * cellSize;
  objectGrid_.resolution = cellSize;
  objectGrid_.cols = std::max(1, int(std::ceil((hi.x() - objectGrid_.origin.x()) / cellSize)) + 1);
  objectGrid_.rows = std::max(1, int(std::ceil((hi.y() - objectGrid_.origin.y()) / cellSize)) + 1);
  std::vector<uint32_t> count(objectGrid_.cellCount() + 1, 0);
  const auto forCells = [&](size_t item, auto&& fn) {
    const Eigen::Vector2d a = objectGrid_.toCell(extents[item].first), b = objectGrid_.toCell(extents[item].second);
    for (int r = std::max(0, int(a.y())); r <= std::min(objectGrid_.rows - 1, int(b.y())); ++r)
      for (int c = std::max(0, int(a.x())); c <= std::min(objectGrid_.cols - 1, int(b.x())); ++c)
        fn(objectGrid_.index(c, r));
  };
  const auto code = [&](size_t item) {
    return item < boxes_.size() ? uint32_t(item) : (uint32_t(item - boxes_.size()) | kCylinderBit);
  };
  for (size_t i = 0; i < extents.size(); ++i) forCells(i, [&](size_t cell) { ++count[cell + 1]; });
  for (size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
  cellStart_ = count;
  items_.assign(count.back(), 0);
  std::vector<uint32_t> fill(count.begin(), count.end() - 1);
  for (size_t i = 0; i < extents.size(); ++i) forCells(i, [&](size_t cell) { items_[fill[cell]++] = code(i); });
}

}  // namespace hdprior
