#include "engine/io/log_map_files.h"

#include <algorithm>
#include <vector>

#include "engine/error.h"

namespace hdprior {
namespace fs = std::filesystem;
namespace {

bool isMapName(const std::string& name, const std::vector<std::string>& parts, const std::string& suffix) {
  return name.size() >= suffix.size() && name.ends_with(suffix) &&
         std::all_of(parts.begin(), parts.end(), [&](const std::string& p) { return name.find(p) != std::string::npos; });
}

// The single file in `dir` whose name contains all of `parts` and ends with `suffix`.
fs::path findOne(const fs::path& dir, const std::vector<std::string>& parts, const std::string& suffix, const char* what) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    if (isMapName(e.path().filename().string(), parts, suffix)) found.push_back(e.path());
  }
  if (ec) throw Error(dir.string(), "cannot list: " + ec.message());
  if (found.empty()) throw Error(dir.string(), std::string("no ") + what + " found");
  if (found.size() > 1) throw Error(dir.string(), std::string("more than one ") + what + " found");
  return found.front();
}

bool holdsVectorMap(const fs::path& dir) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    if (isMapName(e.path().filename().string(), {"log_map_archive_"}, ".json")) return true;
  }
  return false;
}

}  // namespace

LogMapFiles findLogMapFiles(const fs::path& dir) {
  std::error_code ec;
  fs::path mapDir = dir / "map";
  if (!fs::is_directory(mapDir, ec)) {
    if (!fs::is_directory(dir, ec) || !holdsVectorMap(dir)) {
      throw Error(mapDir.string(), "map folder not found (nor a log map's files in " + dir.string() + ")");
    }
    mapDir = dir;
  }
  LogMapFiles files;
  files.vectorMap = findOne(mapDir, {"log_map_archive_"}, ".json", "vector map (log_map_archive_*.json)");
  files.groundHeight = findOne(mapDir, {"_ground_height_surface____"}, ".npy", "ground-height raster (*.npy)");
  files.sim2 = findOne(mapDir, {"___img_Sim2_city"}, ".json", "Sim2 file (*___img_Sim2_city.json)");
  return files;
}

std::string cityFromMapName(const fs::path& vectorMap) {
  const std::string name = vectorMap.filename().string();
  const size_t start = name.rfind("____");
  const size_t end = name.find("_city_", start == std::string::npos ? 0 : start);
  if (start == std::string::npos || end == std::string::npos) return "unknown";
  return name.substr(start + 4, end - start - 4);
}

std::string logIdOfFolder(const fs::path& dir) {
  const fs::path normal = fs::absolute(dir).lexically_normal();
  const std::string id = normal.filename().string();
  return id.empty() ? normal.parent_path().filename().string() : id;
}

}  // namespace hdprior
