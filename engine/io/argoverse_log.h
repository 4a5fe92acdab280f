#pragma once
#include <cstdint>
#include <filesystem>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "engine/geom/pose_trajectory.h"
#include "engine/io/ego_poses.h"
#include "engine/io/lidar_sweep.h"
#include "engine/io/log_map_files.h"

namespace hdprior {

// An Argoverse 2 sensor / TbV log directory. Opening reads the poses, the calibration and
// the sweep list; sweeps load lazily into a bounded cache. Thread-safe.
class ArgoverseLog {
 public:
  explicit ArgoverseLog(const std::filesystem::path& dir, size_t sweepCacheSize = 16);
  ArgoverseLog(const ArgoverseLog&) = delete;
  ArgoverseLog& operator=(const ArgoverseLog&) = delete;

  const std::filesystem::path& dir() const { return dir_; }
  const std::string& id() const { return id_; }
  const std::string& city() const { return city_; }
  const LogMapFiles& mapFiles() const { return mapFiles_; }

  size_t sweepCount() const { return sweepTimestamps_.size(); }
  const std::vector<int64_t>& sweepTimestamps() const { return sweepTimestamps_; }
  std::filesystem::path sweepPath(size_t index) const;
  std::shared_ptr<const LidarSweep> sweep(size_t index) const;  // throws Error on a bad file

  const PoseTrajectory& cityTEgo() const { return cityTEgo_; }
  // The ground truth at every sweep timestamp the poses cover.
  PoseTrajectory cityTEgoAtSweeps() const;
  const SensorCalibration& calibration() const { return calibration_; }

 private:
  std::filesystem::path dir_;
  std::string id_, city_;
  LogMapFiles mapFiles_;
  std::vector<int64_t> sweepTimestamps_;
  PoseTrajectory cityTEgo_;
  SensorCalibration calibration_;

  size_t cacheSize_;
  mutable std::mutex cacheMutex_;
  mutable std::list<std::pair<size_t, std::shared_ptr<const LidarSweep>>> cache_;  // most recent first
};

}  // namespace hdprior
