#pragma once
#include <filesystem>
#include <vector>

namespace hdprior {

class HdMap;

// Writes the HD-map's rasters as north-up GeoTIFFs in city metres into `dir` (created if
// missing): drivable.tif (uint8, 1 = drivable), ground_height.tif (float32, NaN no-data) and
// boundary_distance.tif (float32, metres, negative inside). Each file is written under a
// temporary name and renamed; if any write fails, the files of this call are removed.
// Returns the paths written. Throws Error naming the file.
std::vector<std::filesystem::path> exportMapGeoTiffs(const HdMap& map, const std::filesystem::path& dir);

}  // namespace hdprior
