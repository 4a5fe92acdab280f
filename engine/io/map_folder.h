#pragma once
#include <filesystem>
#include <optional>
#include <string>

#include "engine/io/log_map_files.h"

namespace hdprior {

// A folder holding a log's map and perhaps more of the log, sweeps not needed: a whole sensor log,
// a motion-forecasting or map-change log (map/ and city_SE3_egovehicle.feather), or a log map's
// three files alone. What `hdprior sim --map` reads.
struct MapFolder {
  std::filesystem::path dir;
  std::string id;    // the folder's name, as ArgoverseLog names a log
  std::string city;  // from the vector map's name
  LogMapFiles files;
  std::optional<std::filesystem::path> poses;        // city_SE3_egovehicle.feather, when present
  std::optional<std::filesystem::path> calibration;  // calibration/egovehicle_SE3_sensor.feather, when present
};

// Finds the map files (map/ or the folder itself) and notes which of the poses and the calibration
// are there; reads none of them. Throws Error naming the folder or the map file that is missing.
MapFolder openMapFolder(const std::filesystem::path& dir);

}  // namespace hdprior
