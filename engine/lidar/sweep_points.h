#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/io/lidar_sweep.h"

namespace hdprior {

// The sweep's returns as ego-frame points, in file order.
inline std::vector<Eigen::Vector3d> sweepPoints(const LidarSweep& sweep) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(sweep.points.size());
  for (const LidarPoint& p : sweep.points) points.emplace_back(p.x, p.y, p.z);
  return points;
}

}  // namespace hdprior

namespace hdprior {

// Each return's laser number (ring), in file order.
inline std::vector<uint8_t> sweepRings(const LidarSweep& sweep) {
  std::vector<uint8_t> rings;
  rings.reserve(sweep.points.size());
  for (const LidarPoint& p : sweep.points) rings.push_back(p.laserNumber);
  return rings;
}

}  // namespace hdprior
