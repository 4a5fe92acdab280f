#include "engine/eval/missed_change_events.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <span>

#include "engine/eval/change_scoring.h"
#include "engine/geom/polygon2d.h"

namespace hdprior {

namespace {

// The sweep whose position is nearest to any of the places, and that distance.
std::pair<size_t, double> nearestSweep(const MapChangeLabel& label, const PoseTrajectory& poses,
                                       const std::vector<int64_t>& sweepTimestamps) {
  std::pair<size_t, double> best{0, std::numeric_limits<double>::infinity()};
  for (size_t i = 0; i < sweepTimestamps.size(); ++i) {
    if (!poses.covers(sweepTimestamps[i])) continue;
    const Eigen::Vector2d p = poses.at(sweepTimestamps[i]).translation().head<2>();
    for (const std::vector<Eigen::Vector2d>& place : label.places) {
      const double d = polylineDistance(std::span(&p, 1), place, !label.openLine());
      if (d < best.second) best = {i, d};
    }
  }
  return best;
}

}  // namespace

std::vector<RunEvent> missedChangeEvents(const MapChangeReport& report, const std::vector<MapChangeLabel>& labels,
                                         const PoseTrajectory& poses, const std::vector<int64_t>& sweepTimestamps) {
  std::vector<RunEvent> events;
  for (size_t i : missedChanges(report, labels)) {
    const MapChangeLabel& l = labels[i];
    const auto [frame, distance] = nearestSweep(l, poses, sweepTimestamps);
    if (!std::isfinite(distance)) continue;
    char b[200];
    std::snprintf(b, sizeof b, "%s %s %lld, %.1f m from the drive, not reported", l.change.c_str(), l.element.c_str(),
                  (long long)l.id, l.routeDistance);
    events.push_back({RunEvent::Kind::MissedChange, 0, frame, b});
  }
  std::stable_sort(events.begin(), events.end(), [](const RunEvent& a, const RunEvent& b) { return a.frame < b.frame; });
  return events;
}

}  // namespace hdprior
