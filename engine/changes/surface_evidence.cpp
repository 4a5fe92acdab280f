#include "engine/changes/surface_evidence.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/geom/se2.h"
#include "engine/map/ground_height.h"

namespace hdprior {

namespace {

void addSaturating(uint16_t& count) {
  if (count < std::numeric_limits<uint16_t>::max()) ++count;
}

}  // namespace

SurfaceEvidence SurfaceEvidence::around(const std::vector<Eigen::Vector2d>& positions, double margin, double cell) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(0), hi = Eigen::Vector2d::Constant(0);
  if (!positions.empty()) lo = hi = positions.front();
  for (const Eigen::Vector2d& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  GridGeometry g;
  g.resolution = cell;
  g.origin = (lo.array() - margin).matrix();
  g.cols = int(std::ceil((hi.x() - lo.x() + 2 * margin) / cell));
  g.rows = int(std::ceil((hi.y() - lo.y() + 2 * margin) / cell));
  return SurfaceEvidence(g);
}

void SurfaceEvidence::add(int frame, const LabelledSweep& sweep, const SE3& cityTEgo, const GroundHeight* ground) {
  // labelSweep levelled the points with the pose's roll and pitch; what is left is the yaw.
  const double yaw = yawOf(cityTEgo);
  const Eigen::Matrix2d r = Eigen::Rotation2Dd(yaw).toRotationMatrix();
  const Eigen::Vector3d t = cityTEgo.translation();
  for (size_t i = 0; i < sweep.points.size(); ++i) {
    if (!sweep.ground[i]) continue;
    const Eigen::Vector3d& p = sweep.points[i];
    const Eigen::Vector2d city = r * p.head<2>() + t.head<2>();
    int c, row;
    if (!geometry_.cellOf(city, c, row)) continue;
    SurfaceCell& cell = cells_[geometry_.index(c, row)];
    if (sweep.road[i]) addSaturating(cell.road);
    else addSaturating(cell.offRoad);
    if (sweep.road[i] == kCurbPoint) addSaturating(cell.curb);
    if (ground) {
      const double raster = ground->bilinearAt(city);
      if (std::isfinite(raster)) {
        cell.groundOffsetSum += float(p.z() + t.z() - raster);
        addSaturating(cell.groundOffsetCount);
      }
    }
    if (cell.firstFrame < 0) cell.firstFrame = frame;
    const float range = float(p.head<2>().norm());
    if (range < cell.bestRange) {
      cell.bestRange = range;
      cell.bestFrame = frame;
    }
  }
}

}  // namespace hdprior
