#pragma once
#include <span>

#include <Eigen/Core>

#include "engine/match/match_options.h"
#include "engine/match/match_result.h"

namespace hdprior {

class BoundaryDistance;

// How far the pose can move from `estimate` along each direction of its own frame (along the heading,
// lateral, yaw) before the road points or the curbs say no: the half-width of the interval, searched
// outwards in both senses, over which no more than options.evidenceShare of the road points (at least
// options.evidenceMinPoints) leave the drivable area, and no more than evidenceCurbShare of the curb
// points that lie on the drivable boundary at the estimate (if at least minCurbPoints do) leave it by
// more than evidenceCurbBand, beyond those off at the best pose met so far.
// +infinity where the points allow the whole search range (up to options.evidenceMaxOffset /
// evidenceMaxYawDeg): a plateau, e.g. a narrow strip of road points in a wide junction.
// A point is off the drivable area when its signed distance is beyond options.evidenceMargin.
Eigen::Vector3d plausibleHalfWidths(const BoundaryDistance& sdf, std::span<const Eigen::Vector2d> road,
                                    std::span<const Eigen::Vector2d> curbs, const Eigen::Vector3d& estimate,
                                    const MatchOptions& options);

// Makes result's covariance describe its error rather than the NDT score's local curvature alone: in
// the estimate's frame (yaw scaled by yawLength), along each direction the Laplace information
// observes (its eigenvectors u) the variance is raised to the evidence's, sum_a u_a^2 (half-width_a /
// evidenceKappa)^2, and the map's own error (mapSigma, mapSigmaYawDeg, projected the same way) is
// added; a direction that then exceeds its cap (maxSigma*, projected) or leans on an axis whose
// half-width is unbounded is reported unobservable (no information). Sets observableDirections and, unless the match is
// rejected, its status: Accepted with three, Degenerate with one or two, Rejected with none.
void widenToEvidence(const Eigen::Vector3d& halfWidths, const MatchOptions& options, MatchResult& result);

}  // namespace hdprior
