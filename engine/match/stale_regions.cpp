#include "engine/match/stale_regions.h"

#include <cmath>

#include <Eigen/Geometry>

#include "engine/map/boundary_distance.h"

namespace hdprior {
RegionSelection pointsInAgreeingRegions(const BoundaryDistance& sdf, std::span<const Eigen::Vector2d> road,
                                        std::span<const Eigen::Vector2d> curbs, const Eigen::Vector3d& predicted,
                                        const MatchOptions& o) {
  RegionSelection s;
  if (road.empty()) return s;
  // Regions on a grid over the points' bounding box (key frame).
  Eigen::Vector2d lo = road[0], hi = road[0];
  for (const Eigen::Vector2d& p : road) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double size = o.staleRegionSize;
  const int cols = int((hi.x() - lo.x()) / size) + 1, rows = int((hi.y() - lo.y()) / size) + 1;
  const auto regionOf = [&](const Eigen::Vector2d& p) -> long {
    const long c = long(std::floor((p.x() - lo.x()) / size)), r = long(std::floor((p.y() - lo.y()) / size));
    return c < 0 || r < 0 || c >= cols || r >= rows ? -1 : r * cols + c;
  };
  struct Tally {
    int points = 0, far = 0;
  };
  std::vector<Tally> regions(size_t(cols) * size_t(rows));
  const Eigen::Rotation2Dd R(predicted.z());
  for (const Eigen::Vector2d& p : road) {
    Tally& t = regions[size_t(regionOf(p))];
    ++t.points;
    t.far += !(sdf.cellDistance(R * p + predicted.head<2>()) <= o.staleDistance + o.staleDistancePerMetre * p.norm());
  }
  const auto isStale = [&](const Tally& t) { return double(t.far) > o.staleShare * double(t.points); };
  const auto stale = [&](const Eigen::Vector2d& p) {
    const long i = regionOf(p);
    return i >= 0 && isStale(regions[size_t(i)]);
  };
  for (const Tally& t : regions) s.droppedRegions += t.points > 0 && isStale(t);
  for (const Eigen::Vector2d& p : road) {
    if (stale(p)) ++s.droppedPoints;
    else s.road.push_back(p);
  }
  for (const Eigen::Vector2d& c : curbs)
    if (!stale(c)) s.curbs.push_back(c);
  return s;
}

}  // namespace hdprior
