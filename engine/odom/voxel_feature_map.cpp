#include "engine/odom/voxel_feature_map.h"

#include <algorithm>
#include <unordered_set>

namespace hdprior {

std::vector<Eigen::Vector3f> voxelDownsample(const std::vector<Eigen::Vector3f>& points, float size) {
  std::unordered_set<VoxelKey, VoxelKeyHash> seen;
  seen.reserve(points.size());
  std::vector<Eigen::Vector3f> out;
  for (const auto& p : points) {
    if (seen.insert(voxelOf(p, size)).second) out.push_back(p);
  }
  return out;
}

void VoxelFeatureMap::add(const std::vector<Eigen::Vector3f>& points) {
  const float size = float(options_.voxelSize), minSq = float(options_.minPointSpacing * options_.minPointSpacing);
  for (const auto& p : points) {
    auto& cell = voxels_[voxelOf(p, size)];
    if (int(cell.size()) >= options_.maxPointsPerVoxel) continue;
    const bool crowded = std::any_of(cell.begin(), cell.end(), [&](const Eigen::Vector3f& q) { return (q - p).squaredNorm() < minSq; });
    if (!crowded) cell.push_back(p);
  }
}

void VoxelFeatureMap::removeFarFrom(const Eigen::Vector3f& centre) {
  const float size = float(options_.voxelSize), r = float(options_.radius);
  for (auto it = voxels_.begin(); it != voxels_.end();) {
    const Eigen::Vector3f c = (Eigen::Vector3f(it->first.x, it->first.y, it->first.z) + Eigen::Vector3f::Constant(0.5f)) * size;
    it = (c - centre).squaredNorm() > r * r ? voxels_.erase(it) : std::next(it);
  }
}

int VoxelFeatureMap::nearest(const Eigen::Vector3f& q, int k, float maxDistance, Eigen::Vector3f* out) const {
  const float size = float(options_.voxelSize);
  const int reach = int(std::ceil(maxDistance / size));
  const VoxelKey c = voxelOf(q, size);
  // Keeps the k best in a small sorted array (k is about 5).
  float bestD[16];
  int count = 0;
  k = std::min(k, 16);
  const float maxSq = maxDistance * maxDistance;
  for (int dx = -reach; dx <= reach; ++dx)
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dz = -reach; dz <= reach; ++dz) {
        const auto it = voxels_.find({c.x + dx, c.y + dy, c.z + dz});
        if (it == voxels_.end()) continue;
        for (const auto& p : it->second) {
          const float d = (p - q).squaredNorm();
          if (d > maxSq || (count == k && d >= bestD[k - 1])) continue;
          int j = count < k ? count++ : k - 1;
          while (j > 0 && bestD[j - 1] > d) {
            bestD[j] = bestD[j - 1];
            out[j] = out[j - 1];
            --j;
          }
          bestD[j] = d;
          out[j] = p;
        }
      }
  return count;
}

size_t VoxelFeatureMap::pointCount() const {
  size_t n = 0;
  for (const auto& [key, cell] : voxels_) n += cell.size();
  return n;
}

}  // namespace hdprior
