#pragma once
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "engine/odom/odometry_options.h"

namespace hdprior {

struct VoxelKey {
  int32_t x = 0, y = 0, z = 0;
  bool operator==(const VoxelKey&) const = default;
};
struct VoxelKeyHash {
  size_t operator()(const VoxelKey& k) const {
    return size_t(uint32_t(k.x) * 73856093u ^ uint32_t(k.y) * 19349663u ^ uint32_t(k.z) * 83492791u);
  }
};
inline VoxelKey voxelOf(const Eigen::Vector3f& p, float size) {
  return {int32_t(std::floor(p.x() / size)), int32_t(std::floor(p.y() / size)), int32_t(std::floor(p.z() / size))};
}

// Keeps one point per voxel of `size` (the first one met), in input order.
std::vector<Eigen::Vector3f> voxelDownsample(const std::vector<Eigen::Vector3f>& points, float size);

// The odometry's local map of plane points in the odometry frame: a voxel hash with a cap
// per voxel and a radius around the vehicle, so its size does not grow with the drive.
class VoxelFeatureMap {
 public:
  explicit VoxelFeatureMap(const LocalMapOptions& options = {}) : options_(options) {}

  void add(const std::vector<Eigen::Vector3f>& points);
  void removeFarFrom(const Eigen::Vector3f& centre);
  // Up to k nearest points within maxDistance of q, nearest first; returns how many.
  int nearest(const Eigen::Vector3f& q, int k, float maxDistance, Eigen::Vector3f* out) const;

  bool empty() const { return voxels_.empty(); }
  size_t voxelCount() const { return voxels_.size(); }
  size_t pointCount() const;

 private:
  LocalMapOptions options_;
  std::unordered_map<VoxelKey, std::vector<Eigen::Vector3f>, VoxelKeyHash> voxels_;
};

}  // namespace hdprior
