#include "engine/sim/drivable_lookup.h"

namespace hdprior {

DrivableLookup::DrivableLookup(const VectorMap& map) {
  for (const DrivableArea& a : map.drivableAreas) {
    Ring2 ring = ringOf(a.areaBoundary);
    if (ring.size() < 3) continue;
    Eigen::Vector2d lo = ring.front(), hi = lo;
    for (const Eigen::Vector2d& p : ring) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    rings_.push_back({std::move(ring), lo, hi});
  }
}

bool DrivableLookup::contains(const Eigen::Vector2d& p) const {
  for (const Entry& e : rings_)
    if ((p.array() >= e.lo.array()).all() && (p.array() <= e.hi.array()).all() && ringContains(e.ring, p)) return true;
  return false;
}

}  // namespace hdprior
