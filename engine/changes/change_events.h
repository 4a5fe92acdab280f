#pragma once
#include <vector>

#include "engine/changes/map_change_report.h"
#include "engine/pipeline/run_events.h"

namespace hdprior {

// A map-change event per contradicted drivable area, missing surface, contradicted or missing
// crossing and contradicted lane line (one per line, however many stretches), at the sweep that
// saw it best, and one per run of sweeps the check left out as misaligned, in frame order: "drivable area 17: kerb 2.1 m outside its boundary over 20 m
// (confidence 0.86)", "missing road surface 84 m2, 9.8 m beyond the map (confidence 0.93)".
std::vector<RunEvent> mapChangeEvents(const MapChangeReport& report);

// The events of a run and of its map check in one list, in frame order (the run's first at a frame).
std::vector<RunEvent> mergedEvents(const std::vector<RunEvent>& run, const std::vector<RunEvent>& changes);

}  // namespace hdprior
