#include "engine/sim/crosswalk_sites.h"

#include <algorithm>
#include <unordered_set>

#include "engine/sim/boundary_edit.h"
#include "engine/sim/drivable_lookup.h"

namespace hdprior {
namespace {

using Vec2 = Eigen::Vector2d;

// How far from `from` along `dir` the drivable area reaches (0.25 m steps, at most 40 m).
double reach(const DrivableLookup& drivable, const Vec2& from, const Vec2& dir) {
  double s = 0.0;
  while (s < 40.0 && drivable.contains(from + (s + 0.25) * dir)) s += 0.25;
  return s;
}

}  // namespace


std::vector<PedestrianCrossing> crosswalkSites(const VectorMap& world) {
  const DrivableLookup drivable(world);
  std::unordered_set<int64_t> junctionLanes;
  for (const LaneSegment& l : world.laneSegments)
    if (l.isIntersection) junctionLanes.insert(l.id);
  std::vector<Ring2> taken;
  for (const PedestrianCrossing& c : world.pedestrianCrossings) taken.push_back(crossingOutline(c));
  std::vector<PedestrianCrossing> sites;
  for (const LaneSegment& lane : world.laneSegments) {
    const Polyline3 &L = lane.leftLaneBoundary, &R = lane.rightLaneBoundary;
    if (lane.isIntersection || L.size() < 2 || R.size() < 2 || polylineLength2(ringOf(L)) < 15.0) continue;
    for (bool atStart : {true, false}) {
      const std::vector<int64_t>& next = atStart ? lane.predecessors : lane.successors;
      if (std::none_of(next.begin(), next.end(), [&](int64_t id) { return junctionLanes.count(id) > 0; })) continue;
      const Eigen::Vector3d end = 0.5 * (atStart ? L.front() + R.front() : L.back() + R.back());
      const Eigen::Vector3d inner = 0.5 * (atStart ? L[1] + R[1] : L[L.size() - 2] + R[R.size() - 2]);
      const Vec2 p = end.head<2>(), t = (inner - end).head<2>().normalized(), n(-t.y(), t.x());
      const Vec2 middle = p + 7.5 * t;
      const double left = reach(drivable, middle, n), right = reach(drivable, middle, -n);
      if (left + right < 4.0 || left + right > 40.0) continue;
      PedestrianCrossing site;
      for (double along : {6.0, 9.0}) {
        Polyline3& edge = along == 6.0 ? site.edge1 : site.edge2;
        for (const Vec2& q : {Vec2(p + along * t - right * n), Vec2(p + along * t + left * n)})
          edge.emplace_back(q.x(), q.y(), end.z());
      }
      const Ring2 outline = crossingOutline(site);
      if (std::any_of(taken.begin(), taken.end(), [&](const Ring2& o) { return polylineDistance(outline, o, true) < 1.0; }))
        continue;
      taken.push_back(outline);
      sites.push_back(std::move(site));
    }
  }
  return sites;
}

}  // namespace hdprior
