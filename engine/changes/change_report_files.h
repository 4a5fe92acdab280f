#pragma once
#include <filesystem>
#include <string>

#include "engine/changes/map_change_report.h"

namespace hdprior {

// The report as GeoJSON (RFC 7946 structure; coordinates in the log's city frame, metres, not
// WGS 84): a LineString per boundary stretch the lidar could see and a Polygon per missing
// surface, with properties element, id, verdict, confidence, first_frame, best_frame, evidence
// and change (TbV's vocabulary).
std::string changesGeoJson(const MapChangeReport& report, const std::string& logId);
// The counts: drivable areas per verdict, stretches per verdict, missing surfaces, km driven and observed.
std::string changeSummaryJson(const MapChangeReport& report, const std::string& logId);
// DIR/changes.geojson and DIR/summary.json, each written atomically.
void writeChangeReport(const std::filesystem::path& dir, const MapChangeReport& report, const std::string& logId);

}  // namespace hdprior
