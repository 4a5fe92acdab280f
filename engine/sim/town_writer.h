#pragma once
#include <filesystem>
#include <string>

#include "engine/sim/town_map.h"

namespace hdprior {

// Writes the town's map files into dir/map/ (created if missing), named as in Argoverse 2:
//   log_map_archive_<logId>____<CITY>_city_<n>.json, <logId>_ground_height_surface____<CITY>.npy
//   and <logId>___img_Sim2_city.json, each atomically. Throws Error naming the file.
void writeTownMap(const std::filesystem::path& dir, const std::string& logId, const std::string& city,
                  const TownMap& town);

}  // namespace hdprior
