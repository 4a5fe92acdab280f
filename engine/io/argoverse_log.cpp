#include "engine/io/argoverse_log.h"

#include <algorithm>

#include "engine/error.h"

namespace hdprior {
namespace fs = std::filesystem;

namespace {

std::vector<int64_t> listSweeps(const fs::path& lidarDir) {
  std::error_code ec;
  if (!fs::is_directory(lidarDir, ec)) throw Error(lidarDir.string(), "sweep folder not found");
  std::vector<int64_t> stamps;
  for (const fs::directory_entry& e : fs::directory_iterator(lidarDir, ec)) {
    const fs::path& p = e.path();
    if (p.extension() != ".feather") continue;
    const std::string stem = p.stem().string();
    if (stem.empty() || stem.size() > 19 || !std::all_of(stem.begin(), stem.end(), ::isdigit)) {
      throw Error(p.string(), "sweep file name is not a nanosecond timestamp");
    }
    stamps.push_back(std::stoll(stem));
  }
  if (ec) throw Error(lidarDir.string(), "cannot list: " + ec.message());
  std::sort(stamps.begin(), stamps.end());
  return stamps;
}

}  // namespace

ArgoverseLog::ArgoverseLog(const fs::path& dir, size_t sweepCacheSize)
    : dir_(dir), cacheSize_(std::max<size_t>(1, sweepCacheSize)) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) throw Error(dir.string(), "log directory not found");
  if (!fs::is_directory(dir, ec)) throw Error(dir.string(), "is not a directory");
  id_ = logIdOfFolder(dir);
  sweepTimestamps_ = listSweeps(dir / "sensors" / "lidar");
  cityTEgo_ = readEgoPoses(dir / "city_SE3_egovehicle.feather");
  calibration_ = readSensorCalibration(dir / "calibration" / "egovehicle_SE3_sensor.feather");
  mapFiles_ = findLogMapFiles(dir);
  city_ = cityFromMapName(mapFiles_.vectorMap);
}

fs::path ArgoverseLog::sweepPath(size_t index) const {
  if (index >= sweepTimestamps_.size()) {
    throw Error(dir_.string(), "sweep index " + std::to_string(index) + " out of range (" +
                                   std::to_string(sweepTimestamps_.size()) + " sweeps)");
  }
  return dir_ / "sensors" / "lidar" / (std::to_string(sweepTimestamps_[index]) + ".feather");
}

std::shared_ptr<const LidarSweep> ArgoverseLog::sweep(size_t index) const {
  const fs::path path = sweepPath(index);
  {
    std::lock_guard lock(cacheMutex_);
    for (auto it = cache_.begin(); it != cache_.end(); ++it) {
      if (it->first == index) {
        cache_.splice(cache_.begin(), cache_, it);
        return it->second;
      }
    }
  }
  auto loaded = std::make_shared<const LidarSweep>(readLidarSweep(path));
  std::lock_guard lock(cacheMutex_);
  cache_.emplace_front(index, loaded);
  if (cache_.size() > cacheSize_) cache_.pop_back();
  return loaded;
}

PoseTrajectory ArgoverseLog::cityTEgoAtSweeps() const {
  std::vector<int64_t> stamps;
  std::vector<SE3> poses;
  for (int64_t t : sweepTimestamps_) {
    if (!cityTEgo_.covers(t)) continue;
    stamps.push_back(t);
    poses.push_back(cityTEgo_.at(t));
  }
  return PoseTrajectory(std::move(stamps), std::move(poses), (dir_ / "city_SE3_egovehicle.feather").string());
}

}  // namespace hdprior
