#pragma once
#include <cstdint>
#include <vector>

#include "engine/changes/map_change_report.h"
#include "engine/eval/map_change_labels.h"
#include "engine/geom/pose_trajectory.h"
#include "engine/pipeline/run_events.h"

namespace hdprior {

// The labelled changes of a simulated log that the map check missed (the drive passes within 15 m,
// no report of their element within 5 m: scoreMapChanges' rule), each a missed-change event at the
// sweep (of sweepTimestamps, placed by `poses`) nearest to it: "narrowed drivable area 12, 6.1 m
// from the drive, not reported".
std::vector<RunEvent> missedChangeEvents(const MapChangeReport& report, const std::vector<MapChangeLabel>& labels,
                                         const PoseTrajectory& poses, const std::vector<int64_t>& sweepTimestamps);

}  // namespace hdprior
