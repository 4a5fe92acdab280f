#pragma once
#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/match/match_options.h"

namespace hdprior {

class BoundaryDistance;

// A map that is out of date is wrong in places, not everywhere: the road points are binned in
// square regions of options.staleRegionSize metres (key frame) and a region is left out when more
// than options.staleShare of its points lie farther than options.staleDistance (+ staleDistancePerMetre
// per metre of range) outside the drivable area at the predicted pose: farther than the prediction
// can be off. The rest still match.
struct RegionSelection {
  std::vector<Eigen::Vector2d> road, curbs;  // the points of the regions kept
  size_t droppedRegions = 0, droppedPoints = 0;
};
RegionSelection pointsInAgreeingRegions(const BoundaryDistance& sdf, std::span<const Eigen::Vector2d> road,
                                        std::span<const Eigen::Vector2d> curbs, const Eigen::Vector3d& predicted,
                                        const MatchOptions& options);

}  // namespace hdprior
