#include "engine/map/map_export.h"

#include <functional>

#include "engine/error.h"
#include "engine/map/geotiff.h"
#include "engine/map/hd_map.h"

namespace hdprior {
namespace fs = std::filesystem;

std::vector<fs::path> exportMapGeoTiffs(const HdMap& map, const fs::path& dir) {
  const BoundaryDistance& sdf = map.boundaryDistance();  // checks presence before writing anything
  const GroundHeight& height = map.groundHeight();
  std::error_code ec;
  const bool created = !fs::exists(dir, ec);
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) throw Error(dir.string(), "cannot create output directory: " + ec.message());

  const std::vector<std::pair<fs::path, std::function<void(const fs::path&)>>> outputs = {
      {dir / "drivable.tif",
       [&](const fs::path& p) {
         GeoRaster<uint8_t> r = northUpRaster(map.drivable().geometry(), map.drivable().cellBytes());
         r.description = "drivable area (1 = drivable)";
         writeGeoTiff(p, r);
       }},
      {dir / "ground_height.tif", [&](const fs::path& p) { writeGroundHeightGeoTiff(p, height); }},
      {dir / "boundary_distance.tif",
       [&](const fs::path& p) {
         GeoRaster<float> r = northUpRaster(sdf.geometry(), sdf.values());
         r.description = "signed distance to the drivable boundary (m, negative inside)";
         writeGeoTiff(p, r);
       }},
  };
  std::vector<fs::path> written;
  try {
    for (const auto& [path, write] : outputs) {
      write(path);
      written.push_back(path);
    }
  } catch (...) {
    for (const fs::path& p : written) fs::remove(p, ec);
    if (created) fs::remove(dir, ec);  // only removes it if empty
    throw;
  }
  return written;
}

}  // namespace hdprior
