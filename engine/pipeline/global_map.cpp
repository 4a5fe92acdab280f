#include "engine/pipeline/global_map.h"

#include <unordered_set>

#include "engine/odom/voxel_feature_map.h"

namespace hdprior {

GlobalMap buildGlobalMap(const SweepOf& sweepOf, const Odometry& odometry, const PoseTrajectory& trajectory, double voxel) {
  GlobalMap map;
  std::unordered_set<VoxelKey, VoxelKeyHash> occupied;
  // The keyframes' sweeps give the coverage of all sweeps at a fraction of the cost.
  for (const Keyframe& kf : odometry.keyframes()) {
    const auto sweep = sweepOf(kf.frame);
    const Eigen::Isometry3f T = trajectory.poses()[kf.frame].cast<float>();
    const std::vector<Eigen::Vector3f> points = odometry.deskewed(*sweep, kf.frame);
    for (size_t j = 0; j < points.size(); ++j) {
      const Eigen::Vector3f p = T * points[j];
      if (occupied.insert(voxelOf(p, float(voxel))).second) {
        map.points.push_back(p);
        map.intensity.push_back(float(sweep->points[j].intensity));
      }
    }
  }
  return map;
}

}  // namespace hdprior
