#pragma once
#include <string>
#include <vector>

#include "engine/changes/map_change_report.h"
#include "engine/eval/change_score.h"
#include "engine/eval/map_change_labels.h"

namespace hdprior {

enum class MapElement { DrivableArea, PedestrianCrossing, LaneBoundary };

// A map check scored per element.
struct MapCheckScore {
  ChangeScore drivableAreas, crossings, laneLines;
};

// {"reports", "reports_near_change", "precision", "changes", "changes_found", "recall", "driven_km",
// "false_alarms_per_km"} of the drivable areas, and the same of the crossings in
// "pedestrian_crossing" and of the lane lines in "lane_boundary" (null where undefined).
std::string changeScoreJson(const MapCheckScore& score);

// One line: per element, the reports near a labelled change and the changes found.
std::string changeScoreLine(const MapCheckScore& score);

// The labels (indices) that count for recall and that no report of their element lies near.
std::vector<size_t> missedChanges(const MapChangeReport& report, const std::vector<MapChangeLabel>& labels,
                                  double nearRoute = 15.0, double match = 5.0);

// Every element's reports scored against the labels (scoreMapChanges' defaults).
MapCheckScore scoreMapCheck(const MapChangeReport& report, const std::vector<MapChangeLabel>& labels);

// The reports of one element scored against the labelled changes of that element.
ChangeScore scoreMapChanges(const MapChangeReport& report, const std::vector<MapChangeLabel>& labels,
                            MapElement element = MapElement::DrivableArea, double nearRoute = 15.0, double match = 5.0);

}  // namespace hdprior
