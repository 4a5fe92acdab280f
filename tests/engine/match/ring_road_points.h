// Road points as a ring lidar sees them on a synthetic map, for the matcher's tests.
#pragma once
#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "engine/geom/angles.h"
#include "engine/map/drivable_raster.h"

namespace hdprior::test {

// Circles every 1.5 m out to 30 m, a point every degree, kept where they land on the drivable
// area; in the vehicle's frame (the vehicle at `truth`: x, y, yaw).
inline std::vector<Eigen::Vector2d> ringRoadPoints(const DrivableRaster& drivable, const Eigen::Vector3d& truth) {
  std::vector<Eigen::Vector2d> points;
  for (double r = 3.0; r <= 30.0; r += 1.5) {
    for (double a = 0.0; a < 360.0; a += 1.0) {
      const Eigen::Vector2d p(r * std::cos(a * kDegree), r * std::sin(a * kDegree));
      if (drivable.contains(Eigen::Rotation2Dd(truth.z()) * p + truth.head<2>())) points.push_back(p);
    }
  }
  return points;
}

}  // namespace hdprior::test
