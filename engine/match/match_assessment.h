#pragma once
#include <span>

#include <Eigen/Core>

#include "engine/match/match_options.h"
#include "engine/match/match_result.h"

namespace hdprior {

class BoundaryDistance;
class DrivableRaster;
class NdtGrid;

// Fills in everything a match reports beyond its estimate, the same for every backend:
// score and inlier ratio at result.estimate, the Laplace information of the score on `grid`
// (paper: Omega_scan2map = J^T Omega_NDT J, here -H / (|d1| d2), optionally per distinct
// cell), restricted to the directions the drivable boundary near the points constrains
// (boundary normals, from the signed distance field `sdf`), weak directions dropped; status:
// Rejected for too few points, a timeout, a poor inlier ratio or score, no observable
// direction, or an estimate outside the prediction's gate; Degenerate when only some
// directions are observable; else Accepted. result.initial, iterations and points must be set.
void assessMatch(const NdtGrid& grid, const DrivableRaster& drivable, const BoundaryDistance& sdf, std::span<const Eigen::Vector2d> points,
                 const MatchOptions& options, bool timedOut, MatchResult& result);

// Mahalanobis distance^2 of estimate - initial under the prediction sigma (x, y along and
// across the initial heading, yaw).
double predictionChi2(const Eigen::Vector3d& initial, const Eigen::Vector3d& estimate, const Eigen::Vector3d& sigma);

}  // namespace hdprior
