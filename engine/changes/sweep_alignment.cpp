#include "engine/changes/sweep_alignment.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "engine/geom/polygon2d.h"
#include "engine/geom/se2.h"
#include "engine/lidar/road_points.h"
#include "engine/map/boundary_distance.h"
#include "engine/map/ground_height.h"

namespace hdprior {

namespace {
constexpr int kMinRoadOnRaster = 50;  // road points a sweep needs for its height over the raster
}  // namespace

bool SweepAlignment::offGround(const ChangeOptions& o) const {
  return roadOnRaster >= kMinRoadOnRaster && std::abs(roadOverRaster) > o.groundOffsetLimit;
}

bool SweepAlignment::misaligned(const ChangeOptions& o, double driven) const {
  if (offGround(o)) return true;
  return alignedShifted >= 2 * o.minSamples && alignedShifted >= 2 * std::max(alignedAtPose, 1) && shift.norm() > o.tolerance &&
         polygonsShifted >= 2 && shift.norm() <= o.poseErrorPerMetre * driven;
}

namespace {

// How many of the areas have 2 or more of the points within `near` of their boundary (each point
// counted for the nearest boundary).
int polygonsHolding(const std::vector<Eigen::Vector2d>& points, const std::vector<DrivableArea>& areas, double near) {
  if (points.empty()) return 0;
  Eigen::AlignedBox2d box;
  for (const Eigen::Vector2d& p : points) box.extend(p);
  box.min().array() -= near, box.max().array() += near;
  std::vector<Ring2> rings;
  for (const DrivableArea& a : areas) {
    Eigen::AlignedBox2d b;
    for (const Eigen::Vector3d& v : a.areaBoundary) b.extend(v.head<2>());
    if (b.intersects(box)) rings.push_back(ringOf(a.areaBoundary));
  }
  std::vector<int> count(rings.size(), 0);
  for (const Eigen::Vector2d& p : points) {
    double best = near;
    int at = -1;
    for (size_t k = 0; k < rings.size(); ++k) {
      const double d = polylineDistance(std::span<const Eigen::Vector2d>(&p, 1), rings[k], true);
      if (d <= best) best = d, at = int(k);
    }
    if (at >= 0) ++count[size_t(at)];
  }
  return int(std::count_if(count.begin(), count.end(), [](int n) { return n >= 2; }));
}

// The median height of the road points within `range` of the sensor over the raster, and their count.
std::pair<double, int> roadOverRaster(const LabelledSweep& sweep, const SE3& cityTEgo, const GroundHeight& ground, double range) {
  const Eigen::Matrix2d r = Eigen::Rotation2Dd(yawOf(cityTEgo)).toRotationMatrix();
  const Eigen::Vector3d t = cityTEgo.translation();
  std::vector<double> over;
  for (size_t i = 0; i < sweep.points.size(); ++i) {
    const Eigen::Vector3d& p = sweep.points[i];
    if (sweep.road[i] != kRoadPoint || p.head<2>().norm() > range) continue;
    const double raster = ground.bilinearAt(r * p.head<2>() + t.head<2>());
    if (std::isfinite(raster)) over.push_back(p.z() + t.z() - raster);
  }
  if (over.empty()) return {0.0, 0};
  std::nth_element(over.begin(), over.begin() + over.size() / 2, over.end());
  return {over[over.size() / 2], int(over.size())};
}

}  // namespace

SweepAlignment sweepAlignment(const LabelledSweep& sweep, const SE3& cityTEgo, const BoundaryDistance& distance,
                              const std::vector<DrivableArea>& areas, const GroundHeight* ground, const ChangeOptions& options) {
  const Eigen::Matrix2d r = Eigen::Rotation2Dd(yawOf(cityTEgo)).toRotationMatrix();
  const Eigen::Vector2d t = cityTEgo.translation().head<2>();
  std::vector<Eigen::Vector2d> kerbs;  // city frame, at the pose
  for (size_t i = 0; i < sweep.points.size(); ++i)
    if (sweep.road[i] == kCurbPoint) kerbs.push_back(r * sweep.points[i].head<2>() + t);
  SweepAlignment a;
  a.kerbs = int(kerbs.size());
  if (ground) std::tie(a.roadOverRaster, a.roadOnRaster) = roadOverRaster(sweep, cityTEgo, *ground, options.groundRange);
  const auto aligned = [&](const Eigen::Vector2d& cityShift) {
    int n = 0;
    for (const Eigen::Vector2d& k : kerbs) n += std::abs(distance.cellDistance(k + cityShift)) <= options.cell;
    return n;
  };
  a.alignedAtPose = aligned(Eigen::Vector2d::Zero());
  a.alignedShifted = a.alignedAtPose;
  const int steps = int(std::floor(options.reach / options.cell));
  for (int i = -steps; i <= steps; ++i)
    for (int j = -steps; j <= steps; ++j) {
      const Eigen::Vector2d shift(i * options.cell, j * options.cell);
      const int n = aligned(r * shift);
      if (n > a.alignedShifted || (n == a.alignedShifted && shift.norm() < a.shift.norm())) a.alignedShifted = n, a.shift = shift;
    }
  if (a.shift.norm() <= options.tolerance) return a;
  std::vector<Eigen::Vector2d> lined;
  for (const Eigen::Vector2d& k : kerbs)
    if (std::abs(distance.cellDistance(k + r * a.shift)) <= options.cell) lined.push_back(k + r * a.shift);
  a.polygonsShifted = polygonsHolding(lined, areas, options.cell);
  return a;
}

}  // namespace hdprior
