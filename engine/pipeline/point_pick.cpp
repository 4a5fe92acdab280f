#include "engine/pipeline/point_pick.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "engine/map/hd_map.h"
#include "engine/pipeline/point_labels.h"

namespace hdprior {
namespace {

// Even-odd rule over the polygon's edges in the plane.
bool polygonContains(const std::vector<Eigen::Vector3d>& polygon, const Eigen::Vector2d& p) {
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector3d &a = polygon[i], &b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

std::optional<PickedPoint> nearestPoint(const Eigen::Vector2d& at, const LidarSweep& sweep,
                                        const std::vector<SubmapLabel>& labels, const SE3& cityTEgo, double radius) {
  std::optional<PickedPoint> best;
  for (size_t i = 0; i < sweep.points.size(); ++i) {
    const LidarPoint& p = sweep.points[i];
    const Eigen::Vector3d city = cityTEgo * Eigen::Vector3d(p.x, p.y, p.z);
    const double d = (city.head<2>() - at).norm();
    if (d > radius || (best && d >= best->distance)) continue;
    best = PickedPoint{.index = i, .label = i < labels.size() ? labels[i] : SubmapLabel::Other, .city = city,
                       .range = Eigen::Vector3d(p.x, p.y, p.z).norm(), .heightAboveGround = 0.0, .distance = d,
                       .intensity = p.intensity, .laserNumber = p.laserNumber};
  }
  return best;
}

}  // namespace

Pick pickAt(const Eigen::Vector2d& at, const LidarSweep& sweep, const std::vector<SubmapLabel>& labels, const SE3& cityTEgo,
            const HdMap& map, const PickOptions& options) {
  Pick pick;
  pick.at = at;
  pick.point = nearestPoint(at, sweep, labels, cityTEgo, options.radius);
  if (pick.point) {
    const double ground = map.hasGroundHeight() ? map.groundHeight().bilinearAt(pick.point->city.head<2>())
                                                : std::numeric_limits<double>::quiet_NaN();
    pick.point->heightAboveGround = pick.point->city.z() - ground;
  }
  for (const DrivableArea& area : map.vectorMap().drivableAreas)
    if (area.areaBoundary.size() >= 3 && polygonContains(area.areaBoundary, at)) pick.drivableArea = area.id;
  if (options.ndtCellSize) {
    const NdtGrid& grid = map.ndtGrid(*options.ndtCellSize);
    if (const NdtCell* cell = grid.cellAt(at)) pick.cell = *cell;
    pick.cellSize = *options.ndtCellSize;
  }
  return pick;
}

std::string pickText(const Pick& pick) {
  char b[512];
  std::string out = "pick:";
  if (const auto& p = pick.point) {
    std::snprintf(b, sizeof b, " %s point %zu (%.2f m away) range %.2f m intensity %d laser %d height %.3f m above ground;",
                  labelName(p->label), p->index, p->distance, p->range, p->intensity, p->laserNumber, p->heightAboveGround);
    out += b;
  } else {
    out += " no point;";
  }
  out += pick.drivableArea ? " drivable area " + std::to_string(*pick.drivableArea) : std::string(" not drivable");
  if (pick.cellSize > 0) {
    if (const auto& c = pick.cell) {
      std::snprintf(b, sizeof b, "; ndt cell %.1f m mean %.3f %.3f covariance %.4f %.4f %.4f", pick.cellSize, c->mean.x(),
                    c->mean.y(), c->covariance(0, 0), c->covariance(0, 1), c->covariance(1, 1));
      out += b;
    } else {
      out += "; no ndt cell";
    }
  }
  return out;
}

}  // namespace hdprior
