#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace hdprior {

// One labelled difference between a simulated log's written map and its world (map_change.json,
// docs/formats.md): what changed and where it lies.
struct MapChangeLabel {
  std::string element;  // "drivable_area", "pedestrian_crossing" or "lane_boundary"
  std::string change;   // "removed", "shifted", "added", "narrowed", "kerb_moved", "crosswalk_inserted", "crosswalk_deleted", "lane_line_moved"
  int64_t id = 0;
  // Where it differs: the changed stretch when there is one, else the world's and the map's outlines.
  std::vector<std::vector<Eigen::Vector2d>> places;
  double routeDistance = 0.0;  // metres from the drive

  // Whether its place is an open line (a boundary stretch or lane line that moved), not an outline.
  bool openLine() const { return change == "narrowed" || change == "kerb_moved" || change == "lane_line_moved"; }
};

// A log's labelled changes: its map_change.json (a simulated stale map), nullopt when it has none.
// Throws Error naming the file when it is unreadable.
std::optional<std::vector<MapChangeLabel>> logMapChangeLabels(const std::filesystem::path& logDir);
// Reads map_change.json; throws Error naming the file for a missing or mistyped member.
std::vector<MapChangeLabel> readMapChangeLabels(const std::filesystem::path& file);
std::vector<MapChangeLabel> parseMapChangeLabels(const std::string& json, const std::string& source);

}  // namespace hdprior
