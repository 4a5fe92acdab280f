// A hand-made map_change.json for a log whose map a test edited: the labels a simulated stale map
// would carry (docs/formats.md), so that a map check over it is scored.
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/geom/polygon2d.h"
#include "engine/io/argoverse_log.h"
#include "engine/io/file_bytes.h"
#include "engine/io/vector_map.h"

namespace hdprior::test {

inline nlohmann::json pointsJson(const Ring2& line) {
  nlohmann::json out = nlohmann::json::array();
  for (const Eigen::Vector2d& p : line) out.push_back({p.x(), p.y()});
  return out;
}

// The log's drivable area `id` as its written map has it, labelled as changed.
inline nlohmann::json changedAreaLabel(const std::filesystem::path& log, int64_t id) {
  Ring2 outline;
  for (const DrivableArea& a : readVectorMap(ArgoverseLog(log).mapFiles().vectorMap).drivableAreas)
    if (a.id == id) outline = ringOf(a.areaBoundary);
  return {{"element", "drivable_area"}, {"id", id}, {"change", "shifted"}, {"route_distance_m", 0.0}, {"map_outline", pointsJson(outline)}};
}

// A lane line as the written map draws it, labelled as restriped.
inline nlohmann::json movedLaneLineLabel(const Ring2& line, double offset) {
  return {{"element", "lane_boundary"}, {"id", 1},          {"change", "lane_line_moved"},
          {"route_distance_m", 0.0},   {"offset_m", offset}, {"changed_stretch", pointsJson(line)}};
}

inline void writeMapChangeLabels(const std::filesystem::path& log, const std::vector<nlohmann::json>& changes) {
  const nlohmann::json labels = {{"fraction", 0.3}, {"within_m", nullptr}, {"changes", changes}};
  writeFileAtomically(log / "map_change.json", labels.dump());
}

}  // namespace hdprior::test
