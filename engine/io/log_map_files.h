#pragma once
#include <filesystem>
#include <string>

namespace hdprior {

// The map files of a log (Argoverse 2 / TbV naming).
struct LogMapFiles {
  std::filesystem::path vectorMap;     // log_map_archive_*.json
  std::filesystem::path groundHeight;  // *_ground_height_surface____<CITY>.npy
  std::filesystem::path sim2;          // *___img_Sim2_city.json
};

// The three map files of the log folder `dir`: in its map/ folder (sensor, motion-forecasting and
// map-change logs), else directly in `dir` (a log map shipped on its own). Throws Error naming the
// folder when one is missing or more than one matches.
LogMapFiles findLogMapFiles(const std::filesystem::path& dir);

// "log_map_archive_<log>____PIT_city_47896.json" -> "PIT"; "unknown" when the name does not say.
std::string cityFromMapName(const std::filesystem::path& vectorMap);

// A log's id: the name of its folder.
std::string logIdOfFolder(const std::filesystem::path& dir);

}  // namespace hdprior
