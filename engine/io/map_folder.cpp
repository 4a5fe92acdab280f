#include "engine/io/map_folder.h"

#include "engine/error.h"

namespace hdprior {
namespace fs = std::filesystem;
namespace {

std::optional<fs::path> fileIfPresent(const fs::path& path) {
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) return path;
  return std::nullopt;
}

}  // namespace

MapFolder openMapFolder(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) throw Error(dir.string(), "folder not found");
  if (!fs::is_directory(dir, ec)) throw Error(dir.string(), "is not a directory");
  MapFolder f;
  f.dir = dir;
  f.id = logIdOfFolder(dir);
  f.files = findLogMapFiles(dir);
  f.city = cityFromMapName(f.files.vectorMap);
  f.poses = fileIfPresent(dir / "city_SE3_egovehicle.feather");
  f.calibration = fileIfPresent(dir / "calibration" / "egovehicle_SE3_sensor.feather");
  return f;
}

}  // namespace hdprior
