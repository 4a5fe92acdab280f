#include "engine/match/stale_regions.h"

#include <cmath>
#include <map>
#include <utility>

#include <Eigen/Geometry>

#include "engine/map/boundary_distance.h"

namespace hdprior {
namespace {

using RegionKey = std::pair<int, int>;

RegionKey regionOf(const Eigen::Vector2d& p, double size) {
  return {int(std::floor(p.x() / size)), int(std::floor(p.y() / size))};
}

}  // namespace

RegionSelection pointsInAgreeingRegions(const BoundaryDistance& sdf, std::span<const Eigen::Vector2d> road,
                                        std::span<const Eigen::Vector2d> curbs, const Eigen::Vector3d& predicted,
                                        const MatchOptions& o) {
  struct Tally {
    size_t points = 0, far = 0;
  };
  std::map<RegionKey, Tally> regions;
  const Eigen::Rotation2Dd R(predicted.z());
  for (const Eigen::Vector2d& p : road) {
    Tally& t = regions[regionOf(p, o.staleRegionSize)];
    ++t.points;
    t.far += !(sdf.distance(R * p + predicted.head<2>()) <= o.staleDistance + o.staleDistancePerMetre * p.norm());
  }
  const auto stale = [&](const Eigen::Vector2d& p) {
    const auto it = regions.find(regionOf(p, o.staleRegionSize));
    return it != regions.end() && double(it->second.far) > o.staleShare * double(it->second.points);
  };
  RegionSelection s;
  for (const auto& [key, t] : regions) s.droppedRegions += double(t.far) > o.staleShare * double(t.points);
  for (const Eigen::Vector2d& p : road) {
    if (stale(p)) ++s.droppedPoints;
    else s.road.push_back(p);
  }
  for (const Eigen::Vector2d& c : curbs)
    if (!stale(c)) s.curbs.push_back(c);
  return s;
}

}  // namespace hdprior
