#include "engine/changes/change_report_files.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "engine/io/file_bytes.h"

namespace hdprior {

namespace {

using nlohmann::json;

json coordinates(const std::vector<Eigen::Vector2d>& points, bool closed) {
  json out = json::array();
  for (const Eigen::Vector2d& p : points) out.push_back({p.x(), p.y()});
  if (closed && !points.empty()) out.push_back({points.front().x(), points.front().y()});
  return out;
}

json number(double v) { return std::isfinite(v) ? json(std::round(v * 1000.0) / 1000.0) : json(nullptr); }

json lineString(const std::vector<Eigen::Vector2d>& line) { return {{"type", "LineString"}, {"coordinates", coordinates(line, false)}}; }

json feature(const json& geometry, const json& properties) {
  return {{"type", "Feature"}, {"geometry", geometry}, {"properties", properties}};
}

json polygon(const std::vector<Eigen::Vector2d>& outline) {
  return {{"type", "Polygon"}, {"coordinates", json::array({coordinates(outline, true)})}};
}

json stretchFeature(const BoundaryStretch& s) {
  json evidence = {{"kind", s.evidence},
                   {"offset_m", number(s.offset)},
                   {"samples", s.samples},
                   {"observed", s.observed},
                   {"contradicted", s.contradicted},
                   {"road_beyond", s.open},
                   {"kerb_points", s.curbPoints},
                   {"ground_offset_m", number(s.groundOffset)},
                   {"nearest_view_m", s.nearestView < 1e8 ? number(s.nearestView) : json(nullptr)}};
  if (s.polygonShift.allFinite()) evidence["polygon_shift_m"] = {number(s.polygonShift.x()), number(s.polygonShift.y())};
  json properties = {{"element", "drivable_area"},
                     {"id", s.areaId},
                     {"stretch", s.index},
                     {"verdict", verdictName(s.verdict)},
                     {"confidence", number(s.confidence)},
                     {"first_frame", s.firstFrame},
                     {"best_frame", s.bestFrame},
                     {"evidence", evidence}};
  if (s.verdict == MapVerdict::Contradicted) properties["change"] = "lane_geometry_change";
  return feature(lineString(s.line), properties);
}

json missingFeature(const MissingSurface& m) {
  json evidence = {{"kind", "road_outside_map"},
                   {"area_m2", number(m.area)},
                   {"depth_m", number(m.depth)},
                   {"road_points", m.roadPoints}};
  return {{"type", "Feature"},
          {"geometry", polygon(m.outline)},
          {"properties",
           {{"element", "drivable_area"},
            {"id", nullptr},
            {"verdict", "missing"},
            {"confidence", number(m.confidence)},
            {"first_frame", m.firstFrame},
            {"best_frame", m.bestFrame},
            {"evidence", evidence},
            {"change", "lane_geometry_change"}}}};
}

// In the simulator's labels' terms: a mapped crossing without paint was inserted into the map; a
// painted one the map lacks was deleted from it.
json crossingFeature(const CrossingVerdict& c) {
  json properties = {{"element", "pedestrian_crossing"},
                     {"id", c.id},
                     {"verdict", verdictName(c.verdict)},
                     {"confidence", number(c.confidence)},
                     {"first_frame", c.firstFrame},
                     {"best_frame", c.bestFrame},
                     {"evidence",
                      {{"kind", "brightness"},
                       {"road_cells_inside", c.brightness.insideCells},
                       {"road_cells_around", c.brightness.aroundCells},
                       {"brightness_inside", number(c.brightness.inside)},
                       {"brightness_around", number(c.brightness.around)},
                       {"lift_z", number(c.brightness.z())},
                       {"road_spread", number(c.brightness.spread)},
                       {"controls", c.controls},
                       {"painted_crossings_lift", number(c.paintedLift)},
                       {"road_cells", c.roadCells},
                       {"paint_cells", c.paintCells},
                       {"asphalt_paint_share", number(c.asphaltShare)}}}};
  if (c.verdict == MapVerdict::Contradicted) properties["change"] = "insert_crosswalk";
  return feature(polygon(c.outline), properties);
}

json laneLineFeature(const LaneLineStretch& s) {
  json evidence = {{"kind", s.verdict == MapVerdict::Contradicted ? "paint_beside_line" : "paint_on_line"},
                   {"road_cells_on_line", s.onLine.road},
                   {"paint_cells_on_line", s.onLine.painted},
                   {"asphalt_paint_share", number(s.asphaltShare)}};
  if (s.verdict == MapVerdict::Contradicted)
    evidence["offset_m"] = number(s.offset), evidence["road_cells_at_offset"] = s.atOffset.road, evidence["paint_cells_at_offset"] = s.atOffset.painted;
  json properties = {{"element", "lane_boundary"},
                     {"id", s.laneId},
                     {"side", s.side},
                     {"mark_type", s.markType},
                     {"stretch", s.index},
                     {"verdict", verdictName(s.verdict)},
                     {"confidence", number(s.confidence)},
                     {"first_frame", s.firstFrame},
                     {"best_frame", s.bestFrame},
                     {"evidence", evidence}};
  if (s.verdict == MapVerdict::Contradicted) properties["change"] = "lane_geometry_change";
  return feature(lineString(s.line), properties);
}

json missingCrossingFeature(const MissingCrossing& m) {
  return {{"type", "Feature"},
          {"geometry", polygon(m.outline)},
          {"properties",
           {{"element", "pedestrian_crossing"},
            {"id", nullptr},
            {"verdict", "missing"},
            {"confidence", number(m.confidence)},
            {"first_frame", m.firstFrame},
            {"best_frame", m.bestFrame},
            {"evidence", {{"kind", "paint_outside_map"}, {"road_cells", m.roadCells}, {"paint_cells", m.paintCells}}},
            {"change", "delete_crosswalk"}}}};
}

}  // namespace

std::string changesGeoJson(const MapChangeReport& report, const std::string& logId) {
  json features = json::array();
  for (const BoundaryStretch& s : report.stretches)
    if (s.samples > 0) features.push_back(stretchFeature(s));
  for (const MissingSurface& m : report.missing) features.push_back(missingFeature(m));
  for (const CrossingVerdict& c : report.crossings)
    if (c.roadCells > 0) features.push_back(crossingFeature(c));
  for (const MissingCrossing& m : report.missingCrossings) features.push_back(missingCrossingFeature(m));
  for (const LaneLineStretch& s : report.laneLines) features.push_back(laneLineFeature(s));
  return json{{"type", "FeatureCollection"}, {"name", logId}, {"crs_note", "city frame of the log, metres"}, {"features", features}}
             .dump(1) +
         "\n";
}

std::string changeSummaryJson(const MapChangeReport& report, const std::string& logId) {
  json areas = {{"consistent", 0}, {"contradicted", 0}, {"unobserved", 0}};
  json stretches = {{"consistent", 0}, {"contradicted", 0}, {"unobserved", 0}};
  json contradicted = json::array();
  for (const DrivableAreaVerdict& v : report.drivableAreas) {
    areas[verdictName(v.verdict)] = areas[verdictName(v.verdict)].get<int>() + 1;
    if (v.verdict == MapVerdict::Contradicted) contradicted.push_back(v.id);
  }
  json crossings = {{"consistent", 0}, {"contradicted", 0}, {"unobserved", 0}};
  for (const CrossingVerdict& c : report.crossings)
    crossings[verdictName(c.verdict)] = crossings[verdictName(c.verdict)].get<int>() + 1;
  json laneLines = {{"consistent", 0}, {"contradicted", 0}, {"unobserved", 0}};
  for (const LaneLineStretch& s : report.laneLines)
    laneLines[verdictName(s.verdict)] = laneLines[verdictName(s.verdict)].get<int>() + 1;
  for (const BoundaryStretch& s : report.stretches)
    if (s.samples > 0) stretches[verdictName(s.verdict)] = stretches[verdictName(s.verdict)].get<int>() + 1;
  json misaligned = json::array();
  for (const MisalignedSweep& m : report.misaligned)
    misaligned.push_back({{"frame", m.frame},
                          {"kerb_points", m.alignment.kerbs},
                          {"kerb_points_on_map", m.alignment.alignedAtPose},
                          {"kerb_points_on_map_shifted", m.alignment.alignedShifted},
                          {"polygons_shifted", m.alignment.polygonsShifted},
                          {"road_over_raster_m", number(m.alignment.roadOverRaster)},
                          {"shift_m", {number(m.alignment.shift.x()), number(m.alignment.shift.y())}}});
  return json{{"log_id", logId},
              {"frames", report.frames},
              {"frames_left_out", misaligned},
              {"driven_km", number(report.drivenKm)},
              {"observed_boundary_km", number(report.observedBoundaryKm)},
              {"drivable_areas", areas},
              {"contradicted_drivable_areas", contradicted},
              {"boundary_stretches", stretches},
              {"missing_surfaces", report.missing.size()},
              {"pedestrian_crossings", crossings},
              {"missing_crossings", report.missingCrossings.size()},
              {"lane_line_stretches", laneLines}}
             .dump(2) +
         "\n";
}

void writeChangeReport(const std::filesystem::path& dir, const MapChangeReport& report, const std::string& logId) {
  std::filesystem::create_directories(dir);
  writeFileAtomically(dir / "changes.geojson", changesGeoJson(report, logId));
  writeFileAtomically(dir / "summary.json", changeSummaryJson(report, logId));
}

}  // namespace hdprior
