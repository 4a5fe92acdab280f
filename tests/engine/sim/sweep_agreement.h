// How well two sweeps of a log agree once placed in the city frame: the median distance from
// each point of one to the nearest point of the other. Used to tell motion-compensated sweeps
// (placed with the pose at the sweep timestamp) from raw ones (each return with the pose at
// its own time).
#pragma once
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "engine/geom/pose_trajectory.h"
#include "engine/io/lidar_sweep.h"

namespace hdprior::test {

enum class Placement { AtSweepTimestamp, AtReturnTime };

inline Eigen::Vector3d placePoint(const PoseTrajectory& T, const LidarSweep& s, const LidarPoint& p, Placement how) {
  const int64_t t = how == Placement::AtSweepTimestamp ? s.timestampNs : s.timestampNs + p.offsetNs;
  return T.at(t) * Eigen::Vector3d(p.x, p.y, p.z);
}

// Median over the points of `b` beyond 5 m of the ego of the distance to the nearest point
// of `a` (capped at 1 m; 0.25 m voxel hash), every point placed by `how`.
inline double medianNearest(const PoseTrajectory& T, const LidarSweep& a, const LidarSweep& b, Placement how) {
  const double cell = 0.25;
  const auto key = [&](const Eigen::Vector3d& p, int dx, int dy, int dz) {
    const int64_t x = int64_t(std::floor(p.x() / cell)) + dx, y = int64_t(std::floor(p.y() / cell)) + dy,
                  z = int64_t(std::floor(p.z() / cell)) + dz;
    return (x * 73856093) ^ (y * 19349663) ^ (z * 83492791);
  };
  std::unordered_map<int64_t, std::vector<Eigen::Vector3d>> grid;
  for (const LidarPoint& p : a.points) {
    const Eigen::Vector3d q = placePoint(T, a, p, how);
    grid[key(q, 0, 0, 0)].push_back(q);
  }
  std::vector<double> d;
  for (const LidarPoint& p : b.points) {
    if (std::hypot(double(p.x), double(p.y)) < 5.0) continue;
    const Eigen::Vector3d q = placePoint(T, b, p, how);
    double best = 1.0;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find(key(q, dx, dy, dz));
          if (it == grid.end()) continue;
          for (const Eigen::Vector3d& r : it->second) best = std::min(best, (r - q).norm());
        }
    d.push_back(best);
  }
  std::nth_element(d.begin(), d.begin() + long(d.size() / 2), d.end());
  return d[d.size() / 2];
}

}  // namespace hdprior::test
