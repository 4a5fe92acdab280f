#pragma once
#include <memory>
#include <span>

#include <Eigen/Core>

#include "engine/match/match_options.h"

namespace hdprior {

class DrivableRaster;

// PCL's NormalDistributionsTransform (3-D) as a comparison backend: the road points at
// z = 0 against the filled drivable area (cell centres thinned to pclTargetSpacing, z = 0).
// Coordinates are shifted to the raster's origin so PCL's floats keep centimetres. PCL
// headers stay in the .cpp file.
class PclNdtBackend {
 public:
  PclNdtBackend(const DrivableRaster& drivable, const MatchOptions& options);
  ~PclNdtBackend();
  PclNdtBackend(const PclNdtBackend&) = delete;
  PclNdtBackend& operator=(const PclNdtBackend&) = delete;

  struct Alignment {
    Eigen::Vector3d pose = Eigen::Vector3d::Zero();  // x, y, yaw (roll, pitch and z dropped)
    int iterations = 0;
    bool converged = false;
  };
  Alignment align(std::span<const Eigen::Vector2d> points, const Eigen::Vector3d& initial);
  size_t targetPoints() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hdprior
