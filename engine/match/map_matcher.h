#pragma once
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "engine/match/match_options.h"
#include "engine/match/match_result.h"

namespace hdprior {

class HdMap;
class NdtGrid;
class PclNdtBackend;

// Scan-to-map matching of a key frame's road points (2-D, in its own frame) to the HD map's
// drivable area, from an initial SE(2) pose in the city frame (the odometry's prediction).
// The backend finds the estimate; the same assessment (covariance, degeneracy, acceptance)
// judges it. Not thread-safe (PCL's NDT keeps state); use one matcher per thread.
class MapMatcher {
 public:
  // Throws Error if the options are out of range or the map lacks an NDT grid they name.
  MapMatcher(const HdMap& map, MatchOptions options);
  ~MapMatcher();
  MapMatcher(const MapMatcher&) = delete;
  MapMatcher& operator=(const MapMatcher&) = delete;

  const MatchOptions& options() const { return options_; }
  // curbPoints (road points at curbs, same frame) refine the estimate. Regions of points the map
  // disagrees with at `initial` are left out first (stale_regions.h), and the result's `points`
  // counts the rest.
  MatchResult match(std::span<const Eigen::Vector2d> points, const Eigen::Vector3d& initial,
                    std::span<const Eigen::Vector2d> curbPoints = {});

 private:
  const HdMap& map_;
  MatchOptions options_;
  std::vector<const NdtGrid*> levels_;  // coarse to fine
  std::unique_ptr<PclNdtBackend> pcl_;
};

}  // namespace hdprior
