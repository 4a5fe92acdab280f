#pragma once
#include <span>

#include <Eigen/Core>

namespace hdprior {

class BoundaryDistance;

struct CurbRefinementOptions {
  double huber = 0.15;        // metres: the residual (distance to the boundary) beyond which it counts linearly
  double maxDistance = 1.0;   // curb points farther than this from the boundary at the start are not used
  int minPoints = 20;
  int iterations = 10;
};

struct CurbRefinement {
  Eigen::Vector3d pose = Eigen::Vector3d::Zero();
  int iterations = 0;
  size_t used = 0;  // curb points within maxDistance of the boundary
};

// Moves an SE(2) pose (x, y, yaw) so the curb points (the road's edge seen by the lidar, in the
// pose's frame) lie on the drivable boundary: Gauss-Newton on sum huber(d(T p)), d the signed
// boundary distance. The region NDT is pulled towards cell centres where occlusion (parked cars)
// leaves part of the drivable area unseen; the curbs that are seen are not. The pose moves only across
// its heading and in yaw, never along it (curbs along a straight road do not observe that direction).
CurbRefinement refineOnCurbs(const BoundaryDistance& boundary, std::span<const Eigen::Vector2d> curbPoints,
                             const Eigen::Vector3d& start, const CurbRefinementOptions& options = {});

}  // namespace hdprior
